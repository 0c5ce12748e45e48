// SPDX-License-Identifier: MIT
#include "cal/program.h"

#include <span>
#include <string>

#include "cal/eval.h"
#include "cal/library.h"
#include "cal/parser.h"
#include "cal/ray_variables.h"
#include "core/error.h"

namespace rt::cal {
namespace {}  // namespace

Context::Context(const Program& program)
    : cache_(program.code().slots.size()), generation_(program.generation()) {}

Program::Program(Options options, WarningSink warnings)
    : options_(options), warnings_(std::move(warnings)) {
    // Location 0 is "nowhere", for evaluations started through the API.
    code_.locs.push_back(SourceLoc{-1, 0, 0, -1});
    // Library names are global slots from the start, so a handle to one can be
    // looked up like any other name.
    for (const LibraryFunction& f : Library()) {
        if (options_.rtraceLibrary || !f.rtraceOnly) SlotFor(std::string(f.name));
    }
}

std::int32_t Program::AddFile(std::string_view name) {
    code_.files.emplace_back(name);
    return static_cast<std::int32_t>(code_.files.size() - 1);
}

std::int32_t Program::AddName(std::string_view name) {
    const auto [it, inserted] =
        nameIndex_.try_emplace(std::string(name), static_cast<std::int32_t>(code_.names.size()));
    if (inserted) code_.names.emplace_back(name);
    return it->second;
}

std::string Program::Where(std::uint32_t loc) const {
    const SourceLoc& where = code_.locs[loc];
    if (where.file < 0) return {};
    return code_.files[static_cast<std::size_t>(where.file)] + ":" + std::to_string(where.line) +
           ":" + std::to_string(where.column);
}

std::int32_t Program::SlotFor(const std::string& qualifiedName) {
    const auto it = slotIndex_.find(qualifiedName);
    if (it != slotIndex_.end()) return it->second;
    Slot slot;
    slot.name = qualifiedName;
    slot.library =
        static_cast<std::int16_t>(FindLibraryFunction(qualifiedName, options_.rtraceLibrary));
    code_.slots.push_back(slot);
    const auto index = static_cast<std::int32_t>(code_.slots.size() - 1);
    slotIndex_.emplace(qualifiedName, index);
    return index;
}

std::optional<std::int32_t> Program::Lookup(std::string_view name, std::string_view context) const {
    for (int level = 0;; ++level) {
        const std::optional<std::string> q = QualifiedName(name, context, level);
        if (!q) return std::nullopt;
        const auto it = slotIndex_.find(*q);
        if (it != slotIndex_.end()) return it->second;
    }
}

std::int32_t Program::Insert(std::string_view name, std::string_view context) {
    // A reference binds, at parse time, to the first existing entry from the
    // context outwards; otherwise to a new entry in the current context (or
    // the global one for a library name), defined or not (§9.8).
    if (const std::optional<std::int32_t> found = Lookup(name, context)) return *found;
    if (FindLibraryFunction(name, options_.rtraceLibrary) >= 0) return SlotFor(std::string(name));
    return SlotFor(*QualifiedName(name, context, 0));
}

bool Program::SameBody(std::int32_t a, std::int32_t b) const {
    const Node& x = code_.nodes[static_cast<std::size_t>(a)];
    const Node& y = code_.nodes[static_cast<std::size_t>(b)];
    if (x.op != y.op) return false;
    switch (x.op) {
        case Op::Num:
            return x.num == y.num;
        case Op::Var:
        case Op::Param:
        case Op::Chan:
            return x.a == y.a;
        case Op::Neg:
            return SameBody(x.a, y.a);
        case Op::Add:
        case Op::Sub:
        case Op::Mul:
        case Op::Div:
        case Op::Pow:
            return SameBody(x.a, y.a) && SameBody(x.b, y.b);
        case Op::Call:
        case Op::CallParam:
            if (x.a != y.a || x.n != y.n) return false;
            for (int i = 0; i < x.n; ++i) {
                if (!SameBody(code_.args[static_cast<std::size_t>(x.b + i)],
                              code_.args[static_cast<std::size_t>(y.b + i)])) {
                    return false;
                }
            }
            return true;
    }
    return false;
}

void Program::Define(const Definition& def, const std::string& qualifiedName) {
    const auto it = slotIndex_.find(qualifiedName);
    if (options_.redefinitionWarnings && warnings_ && it != slotIndex_.end()) {
        const Slot& slot = code_.slots[static_cast<std::size_t>(it->second)];
        if (slot.def >= 0) {
            const Definition& old = code_.defs[static_cast<std::size_t>(slot.def)];
            if (old.constant != def.constant || old.params != def.params ||
                !SameBody(old.body, def.body)) {
                warnings_(qualifiedName +
                          (old.constant ? ": redefined constant expression" : ": redefined"));
            } else if (def.params >= 0 && slot.library >= 0) {
                warnings_(qualifiedName + ": definition hides library function");
            }
        } else if (def.params >= 0 && slot.library >= 0) {
            warnings_(qualifiedName + ": definition hides library function");
        }
    }
    const std::int32_t slot = SlotFor(qualifiedName);
    Definition stored = def;
    stored.slot = slot;
    code_.defs.push_back(stored);
    code_.slots[static_cast<std::size_t>(slot)].def =
        static_cast<std::int32_t>(code_.defs.size() - 1);
}

void Program::LoadText(std::string_view text, std::string_view sourceName,
                       std::string_view context) {
    ++generation_;
    Parser parser(*this, text, AddFile(sourceName), context);
    parser.ParseStatements();
}

Expression Program::CompileExpression(std::string_view text, std::string_view sourceName,
                                      std::string_view context) {
    ++generation_;
    Parser parser(*this, text, AddFile(sourceName), context);
    return Expression{parser.ParseExpression()};
}

std::string Program::LoadFile(std::string_view name, const SearchPath& path,
                              std::string_view requestedBy) {
    if (name == ".") return {};
    std::string context = ContextNameForFile(name);
    if (loadedContexts_.count(context) != 0) return context;
    const std::optional<SourceText> source = FindFunctionFile(name, path);
    if (!source) {
        std::string message = "cannot find function file \"" + std::string(name) + "\"";
        if (!requestedBy.empty()) message = std::string(requestedBy) + ": " + message;
        ThrowSystemError(message);
    }
    LoadText(source->text, source->name, context);
    loadedContexts_.insert(context);
    return context;
}

namespace {

/// "name = $n;" for each of `names`, n counting from channel `first`.
std::string ChannelDefinitions(std::span<const char* const> names, int first) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        text += std::string(names[i]) + " = $" + std::to_string(first + static_cast<int>(i)) + ";\n";
    }
    return text;
}

}  // namespace

void Program::DefineRayVariables() {
    LoadText(ChannelDefinitions(kRayVariableNames, 1), "<ray variables>");
}

void Program::DefineBrdfVariables() {
    if (brdfVariables_) return;
    brdfVariables_ = true;
    LoadText(ChannelDefinitions(kBrdfVariableNames, kRayChannelCount + 1), "<BRDF variables>");
}

void Program::DefineRedirectVariables() {
    if (redirectVariables_) return;
    redirectVariables_ = true;
    LoadText(ChannelDefinitions(kRedirectVariableNames, kBrdfChannelCount + 1),
             "<prism variables>");
}

void Program::LoadRayinit(const SearchPath& path) {
    const std::optional<SourceText> source = FindFunctionFile("rayinit.cal", path);
    if (!source) ThrowSystemError("cannot find function file \"rayinit.cal\"");
    LoadText(source->text, source->name);
}

std::optional<Variable> Program::FindVariable(std::string_view name,
                                              std::string_view context) const {
    const std::optional<std::int32_t> slot = Lookup(name, InternalContext(context));
    if (!slot) return std::nullopt;
    const Slot& s = code_.slots[static_cast<std::size_t>(*slot)];
    if (s.def < 0 || code_.defs[static_cast<std::size_t>(s.def)].params >= 0) return std::nullopt;
    return Variable{*slot};
}

std::optional<Function> Program::FindFunction(std::string_view name,
                                              std::string_view context) const {
    const std::optional<std::int32_t> slot = Lookup(name, InternalContext(context));
    if (!slot) return std::nullopt;
    const Slot& s = code_.slots[static_cast<std::size_t>(*slot)];
    if (s.def >= 0) {
        if (code_.defs[static_cast<std::size_t>(s.def)].params < 0) return std::nullopt;
    } else if (s.library < 0) {
        return std::nullopt;
    }
    return Function{*slot};
}

int Program::Arity(Function f) const {
    const Slot& s = code_.slots[static_cast<std::size_t>(f.slot)];
    if (s.def >= 0) return code_.defs[static_cast<std::size_t>(s.def)].params;
    return Library()[static_cast<std::size_t>(s.library)].arity;
}

void Program::Prepare(Context& context) const {
    if (context.cache_.size() != code_.slots.size() || context.generation_ != generation_) {
        context.cache_.assign(code_.slots.size(), {});
        context.generation_ = generation_;
    }
}

namespace {

template <typename F>
double Run(const Program& program, Context& context, F&& body) {
    try {
        return body();
    } catch (const EvalError& e) {
        context.NextEvaluation();
        const std::string where = program.Where(e.loc);
        throw Error(Error::Kind::User, where.empty() ? e.message : where + ": " + e.message);
    }
}

}  // namespace

double Program::Evaluate(Expression e, Context& context) const {
    Prepare(context);
    return Run(*this, context, [&] { return Evaluator(*this, context).TopExpression(e.node); });
}

double Program::Evaluate(Variable v, Context& context) const {
    Prepare(context);
    return Run(*this, context, [&] { return Evaluator(*this, context).TopVariable(v.slot); });
}

double Program::Call(Function f, std::span<const double> args, Context& context) const {
    Prepare(context);
    return Run(*this, context, [&] {
        return Evaluator(*this, context)
            .TopCall(f.slot, args.data(), static_cast<int>(args.size()));
    });
}

}  // namespace rt::cal
