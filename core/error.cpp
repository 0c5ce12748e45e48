// SPDX-License-Identifier: MIT
#include "core/error.h"

namespace rt {

std::string FileLoc::ToString() const {
    if (byteOffset >= 0) return file + ": byte " + std::to_string(byteOffset);
    if (line > 0) return file + ":" + std::to_string(line);
    return file;
}

Error::Error(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}

Error::Error(Kind kind, const FileLoc& loc, const std::string& message)
    : std::runtime_error(loc.ToString() + ": " + message), kind_(kind) {}

Error Error::InternalByInput(const FileLoc& loc, const std::string& message) {
    Error e(Kind::Internal, loc, message);
    e.byInput_ = true;
    return e;
}

Error Error::InternalByInput(const std::string& message) {
    Error e(Kind::Internal, message);
    e.byInput_ = true;
    return e;
}

int Error::ExitCode() const {
    switch (kind_) {
        case Kind::User: return 1;
        case Kind::System: return 2;
        case Kind::Internal: return 3;
    }
    return 3;
}

void ThrowUserError(const FileLoc& loc, const std::string& message) {
    throw Error(Error::Kind::User, loc, message);
}
void ThrowUserError(const std::string& message) { throw Error(Error::Kind::User, message); }
void ThrowSystemError(const std::string& message) { throw Error(Error::Kind::System, message); }

}  // namespace rt
