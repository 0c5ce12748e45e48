// SPDX-License-Identifier: MIT
#include "rtrace/ray_input.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "program/arguments.h"

namespace rt {

RayReader::RayReader(std::istream& in, char format) : in_(in), format_(format) {}

std::optional<InputRay> RayReader::Next() {
    return format_ == 'a' ? NextAscii() : NextBinary();
}

bool RayReader::ReadWord() {
    std::streambuf* sb = in_.rdbuf();
    using Traits = std::streambuf::traits_type;
    int c = sb->sbumpc();
    while (c != Traits::eof() && std::isspace(c)) {
        if (c == '\n') ++line_;
        c = sb->sbumpc();
    }
    if (c == Traits::eof()) {
        in_.setstate(std::ios::eofbit);
        return false;
    }
    wordLine_ = line_;
    word_.clear();
    // Radiance's fgetword() honours quotes; a quoted number is still a number.
    int quote = (c == '"' || c == '\'') ? c : 0;
    if (quote) c = sb->sbumpc();
    while (c != Traits::eof() && (quote ? c != quote : !std::isspace(c))) {
        if (c == '\n') ++line_;
        word_ += static_cast<char>(c);
        c = sb->sbumpc();
    }
    if (c == '\n' && !quote) ++line_;
    return true;
}

std::optional<InputRay> RayReader::NextAscii() {
    double v[6];
    for (int i = 0; i < 6; ++i) {
        if (!ReadWord()) {
            if (i == 0) return std::nullopt;
            throw BadRayError("bad ray at line " + std::to_string(wordLine_));
        }
        if (!IsRealArgument(word_) || word_.find_first_of(" \t\r\n") != std::string::npos)
            throw BadRayError("bad ray at line " + std::to_string(wordLine_));
        v[i] = std::strtod(word_.c_str(), nullptr);
        if (!std::isfinite(v[i])) throw BadRayError("bad ray at line " + std::to_string(wordLine_));
    }
    ++record_;
    return InputRay{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

std::optional<InputRay> RayReader::NextBinary() {
    const std::size_t size = format_ == 'f' ? sizeof(float) : sizeof(double);
    char buf[6 * sizeof(double)];
    in_.read(buf, static_cast<std::streamsize>(6 * size));
    const auto got = static_cast<std::size_t>(in_.gcount());
    const std::uint64_t start = byte_;
    byte_ += got;
    const std::string where = "bad ray at record " + std::to_string(record_ + 1) + " (byte ";
    if (got == 0) return std::nullopt;
    if (got < 6 * size) throw BadRayError(where + std::to_string(byte_) + ")");
    double v[6];
    for (int i = 0; i < 6; ++i) {
        if (size == sizeof(float)) {
            float f;
            std::memcpy(&f, buf + i * size, size);
            v[i] = f;
        } else {
            std::memcpy(&v[i], buf + i * size, size);
        }
        if (!std::isfinite(v[i])) throw BadRayError(where + std::to_string(start + i * size) + ")");
    }
    ++record_;
    return InputRay{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

}  // namespace rt
