// SPDX-License-Identifier: MIT
//
// The function-language parser (internal to cal/): Radiance's scanner and
// recursive-descent grammar (src/common/calexpr.c, caldefn.c;
// radiance-functions.md §9.2–§9.5, §9.8) writing cal/code.h nodes, binding
// names to slots and folding constants as it goes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cal/code.h"
#include "cal/context.h"

namespace rt::cal {

class Program;

class Parser {
  public:
    /// `context` is the bare context name ("" = global).
    Parser(Program& program, std::string_view text, std::int32_t file, std::string_view context);

    /// Statements up to the end of the text.
    void ParseStatements();
    /// One expression filling the whole text; returns its node.
    std::int32_t ParseExpression();

  private:
    static constexpr int kEnd = -1;

    // Scanner (calexpr.c scan()): next_ is the next character that is not
    // white space or part of a comment; Scan() returns the literal character
    // that followed the previous one, so names and numbers end at white space.
    int ReadChar();
    int Scan();
    std::string GetName();
    double GetNumber();
    int GetChannel();

    void Statement();
    std::int32_t E1();
    std::int32_t E2();
    std::int32_t E3();
    std::int32_t E4();
    std::int32_t E5();

    std::int32_t NewNode(Op op, std::uint32_t loc, std::int32_t a = 0, std::int32_t b = 0);
    std::int32_t NewNum(double value, std::uint32_t loc);
    std::int32_t Binary(Op op, std::int32_t left, std::int32_t right, std::uint32_t loc);
    std::uint32_t Here(std::int32_t name = -1);
    bool IsNum(std::int32_t node, double value) const;
    bool IsNum(std::int32_t node) const;
    bool IsConstantFunction(std::int32_t slot) const;
    bool IsConstant(std::int32_t node) const;
    std::int32_t Fold(std::int32_t node);
    [[noreturn]] void Syntax(const std::string& message) const;
    [[noreturn]] void SyntaxAt(std::uint32_t loc, const std::string& message) const;

    Program& program_;
    std::string_view text_;
    std::int32_t file_;
    std::string context_;  // "" or "`name", as appended to qualified names
    std::size_t pos_ = 0;
    int line_ = 1, column_ = 1;  // of text_[pos_]
    int next_ = kEnd;
    int nextLine_ = 1, nextColumn_ = 1;  // of next_
    std::vector<std::string> params_;    // of the function being defined
    int nesting_ = 0;                    // recursion depth of E1/E3
    std::vector<std::uint16_t> depth_;   // expression depth per node made here
    std::size_t firstNode_;
    Context folder_;  // for parse-time evaluation
};

/// The context as appended to qualified names: "" stays "", "sky" is "`sky".
std::string InternalContext(std::string_view context);

/// Radiance's qualname(): the name `name` written in context `context`
/// ("" or "`ctx") looked up `level` context levels up; empty when that level
/// does not exist for this name.
std::optional<std::string> QualifiedName(std::string_view name, std::string_view context,
                                         int level);

}  // namespace rt::cal
