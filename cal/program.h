// SPDX-License-Identifier: MIT
//
// Radiance's function language (calcomp; radiance-functions.md §9): function
// files and expressions are parsed once, constant-folded and compiled to
// cal/code.h's resolved form; a Program then evaluates them with a Context
// per thread.
//
//   rt::cal::Program program;                       // rtrace's library and options
//   program.DefineRayVariables();                   // Dx = $1, … (§10.3)
//   program.LoadRayinit(path);                      // PI, A1, abs, … (§10.5)
//   const std::string ctx = program.LoadFile("skybright.cal", path);
//   const rt::cal::Expression sky = program.CompileExpression("skybr", "brightfunc \"sky\"", ctx);
//   rt::cal::Context context(program);              // one per thread
//   context.SetChannels(&rayQuantities);
//   context.SetArguments(modifierArgs, "brightfunc \"sky\"");
//   context.NextEvaluation();                       // per (modifier, ray)
//   double v = program.Evaluate(sky, context);
//   if (context.mathError() != rt::cal::MathError::None) { /* skip modifier */ }
//
// Loading and compiling mutate the Program and must not overlap evaluations;
// Evaluate/Call are const and may run on many threads, each with its own
// Context. Every error is an rt::Error whose one-line message starts with
// "file:line:column: " (for expressions, the source name given by the caller).
// Evaluation throws only for what Radiance treats as fatal (undefined names,
// missing arguments, bad channels, recursion too deep); math errors set the
// Context's flag and give 0, as in Radiance.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>

#include "cal/code.h"
#include "cal/context.h"
#include "cal/search.h"
#include "core/diagnostics.h"

namespace rt::cal {

struct Options {
    /// `$1 … $channelCount` may be read (rtrace: 27); 0 makes '$' a syntax error.
    int channelCount = 27;
    /// rtrace's additions to the library: arg, erf, erfc, noise3, noise3x/y/z,
    /// fnoise3. Off: only the core library of every calcomp program.
    bool rtraceLibrary = true;
    /// rtrace's "x: redefined" and "definition hides library function" warnings.
    bool redefinitionWarnings = true;
    /// A channel read while folding a constant at parse time: rtrace's fatal
    /// "ray parameter used in constant expression" (false), or 0 as rcalc
    /// reads it (true; for checking against rcalc).
    bool foldedChannelsAreZero = false;
};

/// A compiled expression (a modifier's expression argument).
struct Expression {
    std::int32_t node = -1;
};
/// A name looked up once; it follows later redefinitions of that name.
struct Variable {
    std::int32_t slot = -1;
};
struct Function {
    std::int32_t slot = -1;
};

class Program {
  public:
    explicit Program(Options options = {}, WarningSink warnings = {});

    const Options& options() const { return options_; }

    // ---- Loading (mutates; not concurrently with evaluation) ----

    /// Statements (`name = expr;`, `f(a) : expr;` …) from `text` into
    /// `context` ("" = global). `sourceName` names the text in errors.
    void LoadText(std::string_view text, std::string_view sourceName,
                  std::string_view context = {});

    /// Loads a function file found on `path` into its own context
    /// (ContextNameForFile) unless that context is already loaded, and returns
    /// the context name. "." loads nothing and returns the global context "".
    /// A file found nowhere: rt::Error (System) `cannot find function file "x"`.
    /// `requestedBy` ("scene.rad:12:1", say) starts that message when given.
    std::string LoadFile(std::string_view name, const SearchPath& path,
                         std::string_view requestedBy = {});

    /// rtrace's global definitions Dx = $1 … Lv = $27 (§10.3).
    void DefineRayVariables();
    /// The variables a BRDF material's function reads besides those (§10.4):
    /// NxP = $28 … CbP = $34 (kBrdfChannelCount), defined once, when the
    /// first such material loads (before it, as in Radiance, they are
    /// undefined). Needs Options::channelCount >= kBrdfChannelCount.
    void DefineBrdfVariables();
    /// The variables a prism1/prism2 function reads besides the ray's:
    /// DxA = $35 … DzA = $37 (kRedirectChannelCount), defined once, when the
    /// first such material loads. Needs Options::channelCount >=
    /// kRedirectChannelCount.
    void DefineRedirectVariables();
    /// rayinit.cal from `path` (RAYPATH, else lazyrad's built-in one) into the
    /// global context.
    void LoadRayinit(const SearchPath& path);

    /// One expression (not a statement), parsed in `context`: a modifier's
    /// expression argument.
    Expression CompileExpression(std::string_view text, std::string_view sourceName,
                                 std::string_view context = {});

    // ---- Look-up (once; keep the handle) ----

    /// The variable or function `name` as a reference written in `context`
    /// would find it (file's own definition first, then global), or nullopt
    /// when nothing of that name is defined (functions: nor in the library).
    std::optional<Variable> FindVariable(std::string_view name,
                                         std::string_view context = {}) const;
    std::optional<Function> FindFunction(std::string_view name,
                                         std::string_view context = {}) const;
    /// Declared parameter count: a user function's parameters, or the library
    /// function's declared count (Radiance uses it to choose how colordata
    /// calls its functions, §11.2).
    int Arity(Function f) const;

    // ---- Evaluation (const; one Context per thread) ----

    double Evaluate(Expression e, Context& context) const;
    double Evaluate(Variable v, Context& context) const;
    double Call(Function f, std::span<const double> args, Context& context) const;

    /// Bumped by every load; a Context clears its cache when it sees a new one.
    std::uint64_t generation() const { return generation_; }
    const Code& code() const { return code_; }
    /// "file:line:column" of a source location in code(), "" for none.
    std::string Where(std::uint32_t loc) const;

  private:
    friend class Parser;
    friend class Evaluator;

    std::optional<std::int32_t> Lookup(std::string_view name, std::string_view context) const;
    std::int32_t Insert(std::string_view name, std::string_view context);
    std::int32_t SlotFor(const std::string& qualifiedName);
    void Define(const Definition& def, const std::string& qualifiedName);
    std::int32_t AddFile(std::string_view name);
    std::int32_t AddName(std::string_view name);
    void Prepare(Context& context) const;
    bool SameBody(std::int32_t a, std::int32_t b) const;

    Options options_;
    WarningSink warnings_;
    Code code_;
    std::unordered_map<std::string, std::int32_t> slotIndex_;
    std::unordered_map<std::string, std::int32_t> nameIndex_;  // into code_.names
    std::set<std::string> loadedContexts_;
    bool brdfVariables_ = false;
    bool redirectVariables_ = false;
    std::uint64_t generation_ = 1;
};

}  // namespace rt::cal
