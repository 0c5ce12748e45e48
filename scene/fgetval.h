// SPDX-License-Identifier: MIT
//
// The words of Radiance's text data files as its fgetval() reads them
// (src/common/fgetval.c): white space separates them, '#' (anywhere, even
// inside a word) starts a comment to the end of the line, and a word of 64
// bytes or more is an error. Shared by the data files (data_file.cpp) and
// the font files (font.cpp), which each word their own errors.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace rt::fgetval {

/// fgetval.c reads words into a 64-byte buffer.
inline constexpr std::size_t kMaxWordLength = 63;

inline bool IsSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}
inline bool IsDigit(char c) { return c >= '0' && c <= '9'; }

/// Radiance's isint(): an optional sign and at least one digit.
inline bool IsIntegerWord(std::string_view w) {
    std::size_t k = 0;
    if (k < w.size() && (w[k] == '+' || w[k] == '-')) ++k;
    const std::size_t digits = k;
    while (k < w.size() && IsDigit(w[k])) ++k;
    return k > digits && k == w.size();
}

/// atoi() on glibc: strtol (64-bit long, saturating), then truncated to int.
/// `w` must pass IsIntegerWord.
inline int Atoi(std::string_view w) {
    const std::string word(w);
    const long v = std::strtol(word.c_str(), nullptr, 10);
    return static_cast<int>(static_cast<unsigned int>(static_cast<unsigned long>(v)));
}

/// Reads words in order. Radiance tells some errors apart by whether its
/// reads have reached the end of the file (feof), so this tracks that too.
class Words {
  public:
    explicit Words(std::string_view text) : text_(text) {}

    enum class Status { kWord, kEnd, kTooLong };

    /// The next word (kWord), the end of the text (kEnd; line() is then the
    /// last line, not the one after a final newline), or a word too long
    /// (kTooLong, line() its line).
    Status Next(std::string_view& word) {
        for (;;) {
            while (pos_ < text_.size() && IsSpace(text_[pos_])) Advance();
            if (pos_ == text_.size()) break;
            if (text_[pos_] != '#') {
                const std::size_t start = pos_;
                wordLine_ = line_;
                while (pos_ < text_.size() && !IsSpace(text_[pos_]) && text_[pos_] != '#') {
                    ++pos_;
                    if (pos_ - start > kMaxWordLength) return Status::kTooLong;
                }
                if (pos_ == text_.size()) atEnd_ = true;
                word = text_.substr(start, pos_ - start);
                return Status::kWord;
            }
            while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        }
        atEnd_ = true;
        wordLine_ = std::max(1, line_ - (!text_.empty() && text_.back() == '\n' ? 1 : 0));
        return Status::kEnd;
    }

    /// The line of the last word read, or of the end.
    int line() const { return wordLine_; }
    /// Whether a read has reached the end of the text (feof()).
    bool atEnd() const { return atEnd_; }

  private:
    void Advance() {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int wordLine_ = 1;
    bool atEnd_ = false;
};

}  // namespace rt::fgetval
