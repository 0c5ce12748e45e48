// SPDX-License-Identifier: MIT
#include "cal/parser.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <string>

#include "cal/eval.h"
#include "cal/library.h"
#include "cal/program.h"
#include "core/error.h"

namespace rt::cal {
namespace {

// Real function files nest a few levels deep and their longest sums have a few
// dozen terms; these bounds keep the parser's and the evaluator's recursion
// far from the end of the stack on hostile input.
constexpr int kMaxNesting = 256;
constexpr int kMaxDepth = 1000;
constexpr std::size_t kMaxWord = 127;  // Radiance's RMAXWORD
// Folding a constant runs it at parse time; a constant needing more calls than
// this (exponential recursion, say) is an error rather than a hang.
constexpr std::uint64_t kMaxFoldCalls = 1000000;

// Character classes in the "C" locale whatever the process locale is.
bool IsSpace(int c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
bool IsDigit(int c) { return c >= '0' && c <= '9'; }
bool IsAlpha(int c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool IsNameChar(int c) { return IsAlpha(c) || IsDigit(c) || c == '_' || c == '.' || c == '`'; }

constexpr int kUnset = -2;

struct NestScope {
    explicit NestScope(int& n) : n_(n) { ++n_; }
    ~NestScope() { --n_; }
    NestScope(const NestScope&) = delete;
    NestScope& operator=(const NestScope&) = delete;
    int& n_;
};

}  // namespace

std::string InternalContext(std::string_view context) {
    std::string internal;
    if (!context.empty()) {
        internal.reserve(context.size() + 1);
        internal.push_back('`');
        internal.append(context);
    }
    return internal;
}

std::optional<std::string> QualifiedName(std::string_view name, std::string_view context,
                                         int level) {
    if (!name.empty() && name.front() == '`') {  // current context only
        if (level > 0) return std::nullopt;
        name.remove_prefix(1);
    }
    if (!name.empty() && name.back() == '`') {  // global only
        if (level > 0) return std::nullopt;
        return std::string(name.substr(0, name.size() - 1));
    }
    for (int l = 0; l < level; ++l) {
        if (context.empty()) return std::nullopt;
        const std::size_t next = context.find('`', 1);
        context = next == std::string_view::npos ? std::string_view{} : context.substr(next);
    }
    std::string q(name);
    q += context;
    return q;
}

Parser::Parser(Program& program, std::string_view text, std::int32_t file, std::string_view context)
    : program_(program),
      text_(text),
      file_(file),
      context_(InternalContext(context)),
      firstNode_(program.code_.nodes.size()),
      folder_(program) {
    folder_.folding_ = true;
    folder_.callLimit_ = kMaxFoldCalls;
    folder_.warnings_ = program.warnings_;
    Scan();
}

int Parser::ReadChar() {
    if (pos_ >= text_.size()) return kEnd;
    const int c = static_cast<unsigned char>(text_[pos_++]);
    if (c == '\n') {
        ++line_;
        column_ = 1;
    } else {
        ++column_;
    }
    return c;
}

int Parser::Scan() {
    int literal = kUnset;
    for (;;) {
        nextLine_ = line_;
        nextColumn_ = column_;
        next_ = ReadChar();
        if (literal == kUnset) literal = next_;
        if (next_ == '{') {  // comments nest
            int open = 1;
            while (open > 0) {
                const int c = ReadChar();
                if (c == kEnd) {
                    nextLine_ = line_;
                    nextColumn_ = column_;
                    Syntax("'}' expected");
                }
                open += c == '{' ? 1 : c == '}' ? -1 : 0;
            }
            next_ = ' ';
        }
        if (next_ == kEnd || !IsSpace(next_)) return literal;
    }
}

std::string Parser::GetName() {
    std::string name;
    for (int c = next_; IsNameChar(c); c = Scan()) {
        if (name.size() < kMaxWord) name.push_back(static_cast<char>(c));
    }
    return name;
}

double Parser::GetNumber() {
    std::string s;
    int c = next_;
    while (IsDigit(c) && s.size() < kMaxWord) {
        s.push_back(static_cast<char>(c));
        c = Scan();
    }
    if (c == '.' && s.size() < kMaxWord) {
        s.push_back('.');
        c = Scan();
        if (s.size() == 1 && !IsDigit(c)) Syntax("badly formed number");
        while (IsDigit(c) && s.size() < kMaxWord) {
            s.push_back(static_cast<char>(c));
            c = Scan();
        }
    }
    if ((c == 'e' || c == 'E') && s.size() < kMaxWord) {
        s.push_back(static_cast<char>(c));
        c = Scan();
        if ((c == '-' || c == '+') && s.size() < kMaxWord) {
            s.push_back(static_cast<char>(c));
            c = Scan();
        }
        if (!IsDigit(c)) Syntax("missing exponent");
        while (IsDigit(c) && s.size() < kMaxWord) {
            s.push_back(static_cast<char>(c));
            c = Scan();
        }
    }
    // from_chars does not depend on the locale; out of range it leaves the
    // value alone, so take C's overflow (inf) and underflow (0) answers then.
    double value = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    static_cast<void>(end);
    if (ec == std::errc::result_out_of_range) value = std::strtod(s.c_str(), nullptr);
    return value;
}

int Parser::GetChannel() {
    int n = 0;
    for (int c = next_; IsDigit(c); c = Scan()) n = std::min(n * 10 + (c - '0'), 1000000);
    return n;
}

std::uint32_t Parser::Here(std::int32_t name) {
    program_.code_.locs.push_back(SourceLoc{file_, nextLine_, nextColumn_, name});
    return static_cast<std::uint32_t>(program_.code_.locs.size() - 1);
}

void Parser::Syntax(const std::string& message) const {
    throw Error(Error::Kind::User, program_.code_.files[static_cast<std::size_t>(file_)] + ":" +
                                       std::to_string(nextLine_) + ":" +
                                       std::to_string(nextColumn_) + ": " + message);
}

void Parser::SyntaxAt(std::uint32_t loc, const std::string& message) const {
    throw Error(Error::Kind::User, program_.Where(loc) + ": " + message);
}

std::int32_t Parser::NewNode(Op op, std::uint32_t loc, std::int32_t a, std::int32_t b) {
    Code& code = program_.code_;
    Node node;
    node.op = op;
    node.a = a;
    node.b = b;
    node.loc = loc;
    code.nodes.push_back(node);
    depth_.push_back(1);
    return static_cast<std::int32_t>(code.nodes.size() - 1);
}

std::int32_t Parser::NewNum(double value, std::uint32_t loc) {
    const std::int32_t n = NewNode(Op::Num, loc);
    program_.code_.nodes[static_cast<std::size_t>(n)].num = value;
    return n;
}

std::int32_t Parser::Binary(Op op, std::int32_t left, std::int32_t right, std::uint32_t loc) {
    const auto depthOf = [&](std::int32_t n) -> int {
        const std::size_t i = static_cast<std::size_t>(n);
        return i >= firstNode_ ? depth_[i - firstNode_] : 1;
    };
    const int depth = 1 + std::max(depthOf(left), depthOf(right));
    if (depth > kMaxDepth) SyntaxAt(loc, "expression too deeply nested");
    const std::int32_t n = NewNode(op, loc, left, right);
    depth_.back() = static_cast<std::uint16_t>(depth);
    return n;
}

bool Parser::IsNum(std::int32_t node) const {
    return program_.code_.nodes[static_cast<std::size_t>(node)].op == Op::Num;
}

bool Parser::IsNum(std::int32_t node, double value) const {
    const Node& n = program_.code_.nodes[static_cast<std::size_t>(node)];
    return n.op == Op::Num && n.num == value;
}

bool Parser::IsConstantFunction(std::int32_t slot) const {
    const Code& code = program_.code_;
    const Slot& s = code.slots[static_cast<std::size_t>(slot)];
    if (s.def >= 0) {
        // A user definition masks the library function even if it is a variable.
        const Definition& d = code.defs[static_cast<std::size_t>(s.def)];
        return d.params >= 0 && d.constant;
    }
    return s.library >= 0 && Library()[static_cast<std::size_t>(s.library)].constant;
}

bool Parser::IsConstant(std::int32_t node) const {
    const Code& code = program_.code_;
    const Node& n = code.nodes[static_cast<std::size_t>(node)];
    if (n.op == Op::Call) {
        if (!IsConstantFunction(n.a)) return false;
        for (int i = 0; i < n.n; ++i) {
            const Node& arg =
                code.nodes[static_cast<std::size_t>(code.args[static_cast<std::size_t>(n.b + i)])];
            if (arg.op != Op::Num && !(arg.op == Op::Var && IsConstantFunction(arg.a)))
                return false;
        }
        return true;
    }
    if (n.op == Op::Var) {
        const Slot& s = code.slots[static_cast<std::size_t>(n.a)];
        if (s.def < 0) return false;
        const Definition& d = code.defs[static_cast<std::size_t>(s.def)];
        return d.constant && d.params < 0;
    }
    return false;
}

std::int32_t Parser::Fold(std::int32_t node) {
    const std::uint32_t loc = program_.code_.nodes[static_cast<std::size_t>(node)].loc;
    folder_.cache_.resize(program_.code_.slots.size());
    folder_.NextEvaluation();
    folder_.depth_ = 0;
    double value = 0.0;
    try {
        Evaluator evaluator(program_, folder_, &program_);
        value = evaluator.TopExpression(node);
    } catch (const EvalError& e) {
        SyntaxAt(loc, e.message);
    }
    if (folder_.mathError() != MathError::None) {
        SyntaxAt(loc, "bad constant expression (" + folder_.errorWhat_ + ")");
    }
    return NewNum(value, loc);
}

void Parser::ParseStatements() {
    while (next_ != kEnd) Statement();
}

std::int32_t Parser::ParseExpression() {
    const std::int32_t node = E1();
    if (next_ != kEnd) Syntax("unexpected character");
    return node;
}

void Parser::Statement() {
    if (next_ == ';') {  // empty statement
        Scan();
        return;
    }
    if (!IsAlpha(next_) && next_ != '`') Syntax("illegal variable name");
    const std::uint32_t loc = Here();
    const std::string name = GetName();
    std::vector<std::string> params;
    if (next_ == '(') {
        do {
            Scan();
            if (!IsAlpha(next_)) Syntax("illegal parameter name");
            params.push_back(GetName());
            if (params.back().find('`') != std::string::npos) Syntax("illegal parameter name");
        } while (next_ == ',');
        if (next_ != ')') Syntax("')' expected");
        Scan();
    }
    if (next_ != '=' && next_ != ':') Syntax("'=' or ':' expected");
    Definition def;
    def.constant = next_ == ':';
    def.params = params.empty() ? -1 : static_cast<std::int32_t>(params.size());
    def.loc = loc;
    Scan();
    params_ = std::move(params);
    def.body = E1();
    params_.clear();
    program_.Define(def, *QualifiedName(name, context_, 0));
    if (next_ != kEnd) {
        if (next_ != ';') Syntax("';' expected");
        Scan();
    }
}

std::int32_t Parser::E1() {
    NestScope nest(nesting_);
    if (nesting_ > kMaxNesting) Syntax("expression too deeply nested");
    std::int32_t left = E2();
    while (next_ == '+' || next_ == '-') {
        const Op op = next_ == '+' ? Op::Add : Op::Sub;
        const std::uint32_t loc = Here();
        Scan();
        const std::int32_t right = E2();
        const bool fold = IsNum(left) && IsNum(right);
        left = Binary(op, left, right, loc);
        if (fold) left = Fold(left);
    }
    return left;
}

std::int32_t Parser::E2() {
    std::int32_t left = E3();
    while (next_ == '*' || next_ == '/') {
        Op op = next_ == '*' ? Op::Mul : Op::Div;
        const std::uint32_t loc = Here();
        Scan();
        std::int32_t right = E3();
        if (IsNum(left) && IsNum(right)) {
            left = Fold(Binary(op, left, right, loc));
            continue;
        }
        if (IsNum(right)) {
            const double c = program_.code_.nodes[static_cast<std::size_t>(right)].num;
            if (op == Op::Div) {
                // Radiance multiplies by the reciprocal, which can differ from
                // a true division in the last bit (§9.5 rule 3).
                if (c == 0.0) {
                    SyntaxAt(program_.code_.nodes[static_cast<std::size_t>(right)].loc,
                             "divide by zero constant");
                }
                right = NewNum(1.0 / c, program_.code_.nodes[static_cast<std::size_t>(right)].loc);
                op = Op::Mul;
            } else if (c == 0.0) {
                left = right;  // E * 0: E is dropped unevaluated
                continue;
            }
        } else if (IsNum(left, 0.0)) {
            continue;  // 0 * E, 0 / E
        }
        left = Binary(op, left, right, loc);
    }
    return left;
}

std::int32_t Parser::E3() {
    const std::int32_t left = E4();
    if (next_ != '^') return left;
    const std::uint32_t loc = Here();
    Scan();
    NestScope nest(nesting_);
    if (nesting_ > kMaxNesting) Syntax("expression too deeply nested");
    const std::int32_t right = E3();  // right-associative
    if (IsNum(left) && IsNum(right)) return Fold(Binary(Op::Pow, left, right, loc));
    if (IsNum(left, 0.0)) return left;                                   // 0 ^ E
    if (IsNum(right, 0.0) || IsNum(left, 1.0)) return NewNum(1.0, loc);  // E ^ 0, 1 ^ E
    if (IsNum(right, 1.0)) return left;                                  // E ^ 1
    return Binary(Op::Pow, left, right, loc);
}

std::int32_t Parser::E4() {
    if (next_ == '-') {
        const std::uint32_t loc = Here();
        Scan();
        const std::int32_t operand = E5();
        Node& n = program_.code_.nodes[static_cast<std::size_t>(operand)];
        if (n.op == Op::Num) {
            n.num = -n.num;
            return operand;
        }
        if (n.op == Op::Neg) return n.a;
        // Depth bookkeeping as for a binary node with one operand.
        return Binary(Op::Neg, operand, operand, loc);
    }
    if (next_ == '+') Scan();
    return E5();
}

std::int32_t Parser::E5() {
    Code& code = program_.code_;
    if (next_ == '(') {
        Scan();
        const std::int32_t inner = E1();
        if (next_ != ')') Syntax("')' expected");
        Scan();
        return inner;
    }
    if (next_ == '$' && program_.options_.channelCount > 0) {
        const std::uint32_t loc = Here();
        Scan();
        return NewNode(Op::Chan, loc, GetChannel());
    }
    if (IsAlpha(next_) || next_ == '`') {
        const int nameLine = nextLine_, nameColumn = nextColumn_;
        const std::string name = GetName();
        code.locs.push_back(SourceLoc{file_, nameLine, nameColumn, program_.AddName(name)});
        const std::uint32_t loc = static_cast<std::uint32_t>(code.locs.size() - 1);
        const auto param = std::find(params_.begin(), params_.end(), name);
        const bool isParam = param != params_.end();
        const std::int32_t target = isParam ? static_cast<std::int32_t>(param - params_.begin())
                                            : program_.Insert(name, context_);
        std::int32_t node;
        if (next_ == '(') {
            std::vector<std::int32_t> args;
            int depth = 1;
            do {
                Scan();
                args.push_back(E1());
                const std::size_t i = static_cast<std::size_t>(args.back());
                depth = std::max(depth, i >= firstNode_ ? depth_[i - firstNode_] + 1 : 2);
            } while (next_ == ',');
            if (next_ != ')') Syntax("')' expected");
            if (args.size() > 0xffff) Syntax("too many arguments");
            Scan();
            node = NewNode(isParam ? Op::CallParam : Op::Call, loc, target,
                           static_cast<std::int32_t>(code.args.size()));
            code.nodes[static_cast<std::size_t>(node)].n = static_cast<std::uint16_t>(args.size());
            code.args.insert(code.args.end(), args.begin(), args.end());
            if (depth > kMaxDepth) SyntaxAt(loc, "expression too deeply nested");
            depth_.back() = static_cast<std::uint16_t>(depth);
        } else {
            node = NewNode(isParam ? Op::Param : Op::Var, loc, target);
        }
        if (IsConstant(node)) node = Fold(node);
        return node;
    }
    if (IsDigit(next_) || next_ == '.') {
        const std::uint32_t loc = Here();
        return NewNum(GetNumber(), loc);
    }
    Syntax("unexpected character");
}

}  // namespace rt::cal
