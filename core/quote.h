// SPDX-License-Identifier: MIT
//
// Radiance's word quoting (fputword(), printargs()): how a word is written so
// that Radiance's word readers (the scene reader, nextword() for @files) read it
// back whole. rtrace's header and -e banner, rvimage's picture metadata and
// xform's scene text all write words this way.
//
//   QuoteWords({"rtrace", "-e", "my log"})  // rtrace -e "my log"
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace rt {

/// `word` as it is, or in quotes when it holds white space or a quote: single
/// quotes around a word whose last quote character is `"`, double quotes
/// otherwise (fputword()). An empty word is written `""`, where fputword()
/// writes nothing and the word would be lost to a reader.
std::string QuoteWord(std::string_view word);

/// printargs() without its newline: every word quoted, joined by single spaces.
std::string QuoteWords(std::span<const std::string> words);

}  // namespace rt
