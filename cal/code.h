// SPDX-License-Identifier: MIT
//
// The compiled form of function-language text (internal to cal/): a flat
// array of expression nodes whose names are already resolved to slot numbers,
// so evaluation does no name look-up. Radiance keeps a linked EPNODE tree and
// a global VARDEF hash table (src/common/calexpr.c, caldefn.c); a slot here is
// a VARDEF, a Definition an EPNODE definition.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rt::cal {

enum class Op : std::uint8_t {
    Num,    // num
    Var,    // a = slot
    Param,  // a = parameter index (0-based) of the enclosing function
    Chan,   // a = channel number as written
    Neg,    // a = operand
    Add,    // a, b = operands
    Sub,
    Mul,
    Div,
    Pow,
    Call,       // a = slot, b = first argument in Code::args, n = argument count
    CallParam,  // a = parameter index holding the function's name; b, n as Call
};

struct Node {
    double num = 0.0;
    std::int32_t a = 0;
    std::int32_t b = 0;
    std::uint32_t loc = 0;  // index into Code::locs
    std::uint16_t n = 0;
    Op op = Op::Num;
};

/// Where a node came from, for errors at evaluation time.
struct SourceLoc {
    std::int32_t file = 0;    // index into Code::files
    std::int32_t line = 0;    // 1-based
    std::int32_t column = 0;  // 1-based
    std::int32_t name = -1;   // index into Code::names: the name as written, if any
};

struct Definition {
    std::int32_t slot = 0;
    std::int32_t params = -1;  // parameter count; -1 for a variable
    std::int32_t body = 0;     // node
    bool constant = false;     // defined with ':'
    // A `:` variable whose value parse-time folding computed: frozen for good,
    // as Radiance stores it in the definition.
    bool frozen = false;
    double frozenValue = 0.0;
    std::uint32_t loc = 0;
};

/// One qualified name: `name` for the global context, "name`ctx" in a file's.
struct Slot {
    std::string name;
    std::int32_t def = -1;      // latest definition, -1 if none
    std::int16_t library = -1;  // library function of this (global) name, -1 if none
};

struct Code {
    std::vector<Node> nodes;
    std::vector<std::int32_t> args;  // call arguments, contiguous per call
    std::vector<Definition> defs;
    std::vector<Slot> slots;
    std::vector<SourceLoc> locs;
    std::vector<std::string> files;
    std::vector<std::string> names;
};

}  // namespace rt::cal
