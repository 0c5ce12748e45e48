// SPDX-License-Identifier: MIT
#include "scene/reader.h"

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "scene/object_types.h"

namespace rt {
namespace {

// Radiance splits words at 511 characters; we refuse absurd ones instead, so a
// binary file without white space cannot make us buffer gigabytes.
constexpr std::size_t kMaxWordLength = 1 << 16;
constexpr std::size_t kMaxLineLength = 1 << 20;
// Far above any real primitive; stops a garbage count from looking plausible.
constexpr long long kMaxArgumentCount = 100'000'000;

bool IsSpace(int c) { return c != EOF && std::isspace(static_cast<unsigned char>(c)); }

std::string Describe(const SceneObject& object) {
    return object.type + " \"" + PrintableWord(object.name) + "\"";
}

}  // namespace

int IstreamCharSource::Get() {
    const auto c = buf_->sbumpc();
    return c == std::char_traits<char>::eof() ? EOF : c;
}

SceneTextReader::SceneTextReader(CharSource& source, std::string name)
    : source_(source), name_(std::move(name)) {}

int SceneTextReader::Peek() {
    if (peeked_ == -2) peeked_ = source_.Get();
    return peeked_;
}

int SceneTextReader::Get() {
    const int c = Peek();
    peeked_ = -2;
    if (c == '\n') ++line_;
    return c;
}

std::optional<std::string> SceneTextReader::Word() {
    while (IsSpace(Peek())) Get();
    if (Peek() == EOF) return std::nullopt;
    const FileLoc start = Here();
    std::string word;
    const int first = Peek();
    if (first == '"' || first == '\'') {
        Get();
        for (int c = Get(); c != first; c = Get()) {
            if (c == EOF) ThrowUserError(start, "unterminated quoted word");
            if (word.size() >= kMaxWordLength) ThrowUserError(start, "word too long");
            word.push_back(static_cast<char>(c));
        }
        return word;
    }
    while (Peek() != EOF && !IsSpace(Peek())) {
        if (word.size() >= kMaxWordLength) ThrowUserError(start, "word too long");
        word.push_back(static_cast<char>(Get()));
    }
    return word;
}

std::string SceneTextReader::RequireWord(const char* what, const SceneObject& object) {
    auto word = Word();
    if (!word) {
        if (object.name.empty() && object.type.empty()) {
            ThrowUserError(Here(), std::string("unexpected end of file: expected ") + what +
                                       " after modifier \"" + PrintableWord(object.modifier) +
                                       "\"");
        }
        ThrowUserError(Here(), "unexpected end of file in " + Describe(object) +
                                   ": expected " + what);
    }
    return *word;
}

long long SceneTextReader::Count(const char* what, const SceneObject& object) {
    while (IsSpace(Peek())) Get();
    const FileLoc loc = Here();
    const std::string word = RequireWord(what, object);
    long long value = -1;
    if (IsIntegerWord(word)) {
        const char* begin = word.data() + (word[0] == '+' ? 1 : 0);
        const auto [end, ec] = std::from_chars(begin, word.data() + word.size(), value);
        if (ec != std::errc() || end != word.data() + word.size()) value = -1;
    }
    if (value < 0 || value > kMaxArgumentCount) {
        ThrowUserError(loc,
                       std::string("bad ") + what + " '" + PrintableWord(word) + "' in " +
                           Describe(object));
    }
    return value;
}

std::string SceneTextReader::RestOfLine(bool continuation) {
    std::string text;
    for (int c = Get(); c != EOF; c = Get()) {
        if (c == '\r' && Peek() == '\n') continue;
        if (c == '\n' && !(continuation && !text.empty() && text.back() == '\\')) break;
        if (text.size() >= kMaxLineLength) ThrowUserError(Here(), "line too long");
        text.push_back(static_cast<char>(c));
    }
    return text;
}

SceneItem SceneTextReader::Next() {
    while (IsSpace(Peek())) Get();
    SceneItem item;
    item.loc = Here();
    const int c = Peek();
    if (c == EOF) return item;
    if (c == '#') {
        item.kind = SceneItemKind::Comment;
        item.text = RestOfLine(false);
        return item;
    }
    if (c == '!') {
        Get();
        item.kind = SceneItemKind::Command;
        item.text = RestOfLine(true);
        return item;
    }

    item.kind = SceneItemKind::Object;
    SceneObject& object = item.object;
    object.loc = item.loc;
    object.modifier = *Word();
    if (object.modifier.find('\t') != std::string::npos) {
        ThrowUserError(object.loc,
                       "illegal tab in modifier \"" + PrintableWord(object.modifier) + "\"");
    }
    while (IsSpace(Peek())) Get();
    const FileLoc typeLoc = Here();
    std::string type = RequireWord("object type", object);
    if (!IsKnownObjectType(type)) {
        ThrowUserError(typeLoc, "unknown object type '" + PrintableWord(type) + "'");
    }
    object.type = std::move(type);
    object.name = RequireWord("identifier", object);
    if (object.name.find('\t') != std::string::npos) {
        ThrowUserError(object.loc,
                       "illegal tab in identifier \"" + PrintableWord(object.name) + "\"");
    }
    if (object.type == "alias") {
        object.sargs.push_back(RequireWord("alias reference", object));
        return item;
    }
    if (object.modifier == "inherit") {
        ThrowUserError(object.loc, "inappropriate use of 'inherit' modifier in " +
                                       Describe(object));
    }
    const long long nsargs = Count("string argument count", object);
    for (long long i = 0; i < nsargs; ++i) {
        object.sargs.push_back(RequireWord("string argument", object));
    }
    while (IsSpace(Peek())) Get();
    const FileLoc intLoc = Here();
    const std::string intCount = RequireWord("integer argument count", object);
    if (!IsIntegerWord(intCount) || intCount.find_first_not_of("+-0") != std::string::npos) {
        ThrowUserError(intLoc, "bad integer argument count '" + PrintableWord(intCount) +
                                   "' in " + Describe(object) + " (must be 0)");
    }
    const long long nrargs = Count("real argument count", object);
    for (long long i = 0; i < nrargs; ++i) {
        while (IsSpace(Peek())) Get();
        const FileLoc realLoc = Here();
        const std::string word = RequireWord("real argument", object);
        const auto value = ParseRealWord(word);
        if (!value) {
            ThrowUserError(realLoc, "bad real argument '" + PrintableWord(word) + "' in " +
                                        Describe(object));
        }
        object.rargs.push_back(*value);
    }
    return item;
}

bool IsIntegerWord(std::string_view word) {
    std::size_t i = 0;
    if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
    if (i == word.size()) return false;
    for (; i < word.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(word[i]))) return false;
    }
    return true;
}

std::optional<double> ParseRealWord(std::string_view word) {
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t start = i;
        while (i < word.size() && std::isdigit(static_cast<unsigned char>(word[i]))) ++i;
        return i - start;
    };
    if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
    const std::size_t mantissaStart = i;
    std::size_t mantissaDigits = digits();
    if (i < word.size() && word[i] == '.') {
        ++i;
        mantissaDigits += digits();
    }
    if (mantissaDigits == 0) return std::nullopt;
    if (i < word.size() && (word[i] == 'e' || word[i] == 'E')) {
        ++i;
        if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
        if (digits() == 0) return std::nullopt;
    }
    if (i != word.size()) return std::nullopt;

    const bool negative = mantissaStart > 0 && word[0] == '-';
    double value = 0;
    const char* begin = word.data() + mantissaStart;
    const char* end = word.data() + word.size();
    const auto [stop, ec] = std::from_chars(begin, end, value);
    if (ec == std::errc::result_out_of_range) {
        // Underflow is harmless (Radiance's atof gives 0 or a denormal); overflow is not.
        const std::string copy(begin, end);
        value = std::strtod(copy.c_str(), nullptr);
        if (!std::isfinite(value)) return std::nullopt;
    } else if (ec != std::errc() || stop != end) {
        return std::nullopt;
    }
    return negative ? -value : value;
}

std::string PrintableWord(std::string_view word) {
    constexpr std::size_t kMaxShown = 60;
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    for (std::size_t i = 0; i < word.size(); ++i) {
        if (i == kMaxShown) {
            out += "...";
            break;
        }
        const auto c = static_cast<unsigned char>(word[i]);
        if (c < 0x20 || c >= 0x7f) {
            out += "\\x";
            out.push_back(kHex[c >> 4]);
            out.push_back(kHex[c & 15]);
        } else {
            out.push_back(static_cast<char>(c));
        }
    }
    return out;
}

std::string ShellQuote(std::string_view text) {
    std::string out = "'";
    for (const char c : text) {
        if (c == '\'') {
            out += "'\\''";
        } else {
            out.push_back(c);
        }
    }
    return out + "'";
}

int InheritedCommandDepth() {
    const char* value = std::getenv(kCommandDepthVariable);
    if (value == nullptr || !IsIntegerWord(value)) return 0;
    return std::max(0, std::atoi(value));
}

CommandPipe::CommandPipe(const std::string& command, const std::string& pathPrefix,
                         int depth) {
    // Environment changes are made by the shell, so they reach the child only.
    std::string script;
    if (!pathPrefix.empty()) script += "PATH=" + ShellQuote(pathPrefix) + ":\"$PATH\"; export PATH; ";
    script += std::string(kCommandDepthVariable) + "=" + std::to_string(depth) + "; export " +
              kCommandDepthVariable + "; exec </dev/null\n" + command;
    std::fflush(nullptr);
    pipe_ = popen(script.c_str(), "r");
    if (pipe_ != nullptr) source_ = std::make_unique<FileCharSource>(pipe_);
}

CommandPipe::~CommandPipe() {
    if (pipe_ != nullptr) pclose(pipe_);
}

std::string CommandPipe::Finish() {
    if (pipe_ == nullptr) return "cannot execute";
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    source_.reset();
    if (status == -1) return "cannot get exit status";
    if (WIFEXITED(status)) {
        return WEXITSTATUS(status) == 0 ? "" : "exit status " + std::to_string(WEXITSTATUS(status));
    }
    if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
    return "abnormal termination";
}

}  // namespace rt
