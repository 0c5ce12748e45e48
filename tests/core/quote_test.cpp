// SPDX-License-Identifier: MIT
#include "core/quote.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace rt {
namespace {

TEST(QuoteWord, QuotesLikeFputword) {
    struct Case {
        std::string_view word, written;
    };
    constexpr Case kCases[] = {
        {"plain", "plain"},
        {"a b", "\"a b\""},
        {"tab\there", "\"tab\there\""},
        {"say\"hi\"", "'say\"hi\"'"},
        {"say \"hi\" now", "'say \"hi\" now'"},
        {"it's", "\"it's\""},
        {"a\"b'c", "\"a\"b'c\""},  // the last quote character decides
    };
    for (const Case& c : kCases) EXPECT_EQ(QuoteWord(c.word), c.written) << c.word;
}

TEST(QuoteWord, EmptyWordSurvivesAReader) { EXPECT_EQ(QuoteWord(""), "\"\""); }

TEST(QuoteWords, JoinsLikePrintargs) {
    EXPECT_EQ(QuoteWords(std::vector<std::string>{"rtrace", "-ab", "2"}), "rtrace -ab 2");
    EXPECT_EQ(QuoteWords(std::vector<std::string>{"rtrace", "-e", "my log"}),
              "rtrace -e \"my log\"");
    EXPECT_EQ(QuoteWords(std::vector<std::string>{}), "");
}

}  // namespace
}  // namespace rt
