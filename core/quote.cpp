// SPDX-License-Identifier: MIT
#include "core/quote.h"

#include <cctype>

namespace rt {

std::string QuoteWord(std::string_view word) {
    bool hasSpace = false;
    char quote = 0;
    for (char c : word) {
        if (std::isspace(static_cast<unsigned char>(c))) hasSpace = true;
        else if (c == '"') quote = '\'';
        else if (c == '\'') quote = '"';
    }
    if (!hasSpace && !quote && !word.empty()) return std::string(word);
    if (!quote) quote = '"';
    return quote + std::string(word) + quote;
}

std::string QuoteWords(std::span<const std::string> words) {
    std::string s;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i) s += ' ';
        s += QuoteWord(words[i]);
    }
    return s;
}

}  // namespace rt
