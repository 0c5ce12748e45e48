// SPDX-License-Identifier: MIT
#include "cal/builtin_files.h"

namespace rt::cal {

std::optional<std::string_view> FindBuiltinFile(std::string_view name) {
    for (const BuiltinFile& file : BuiltinFiles()) {
        if (file.name == name) return file.text;
    }
    return std::nullopt;
}

}  // namespace rt::cal
