// SPDX-License-Identifier: MIT
//
// The language's evaluation model through the API: lazy arguments evaluated
// once, the value cache and its clock, frozen constants, contexts, handles,
// errors with their file:line:column, the recursion guard, and threads.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "cal/ray_variables.h"
#include "tests/cal/cal_test_util.h"

namespace rt::cal {
namespace {

using testing::Channels;
using testing::ErrorOf;
using testing::RtraceProgram;

// Counts how often each channel is read.
struct CountingChannels : ChannelSource {
    mutable std::vector<int> reads = std::vector<int>(30, 0);
    double Channel(int n) const override {
        ++reads[static_cast<std::size_t>(n)];
        return n * 1.5;
    }
};

double Eval(Program& program, const std::string& expr, Context& context,
            const std::string& ctx = {}) {
    return program.Evaluate(program.CompileExpression(expr, "expr", ctx), context);
}

TEST(CalLanguage, ArgumentsAreLazyAndEvaluatedOncePerCall) {
    Program program;
    program.LoadText("f(a) = a + a + a;  g(a, b) = if(a, 1, b);  h(a) = f(a) * 2;", "f.cal");
    CountingChannels channels;
    Context context(program);
    context.SetChannels(&channels);
    context.NextEvaluation();
    EXPECT_DOUBLE_EQ(Eval(program, "f($1 * 2)", context), 9.0);
    EXPECT_EQ(channels.reads[1], 1);  // three uses, one evaluation
    EXPECT_DOUBLE_EQ(Eval(program, "g(1, $2)", context), 1.0);
    EXPECT_EQ(channels.reads[2], 0);  // never needed, never evaluated
    EXPECT_DOUBLE_EQ(Eval(program, "h($3)", context), 27.0);
    EXPECT_EQ(channels.reads[3], 1);  // passed on through f: still once
}

TEST(CalLanguage, VariablesAreComputedOncePerEvaluation) {
    Program program;
    program.LoadText("x = $1; y = x * x + x;", "v.cal");
    CountingChannels channels;
    Context context(program);
    context.SetChannels(&channels);
    const Variable y = *program.FindVariable("y");
    context.NextEvaluation();
    EXPECT_DOUBLE_EQ(program.Evaluate(y, context), 1.5 * 1.5 + 1.5);
    EXPECT_DOUBLE_EQ(program.Evaluate(y, context), 1.5 * 1.5 + 1.5);
    EXPECT_EQ(channels.reads[1], 1);
    context.NextEvaluation();  // a new ray: recomputed
    program.Evaluate(y, context);
    EXPECT_EQ(channels.reads[1], 2);
    // Also through the handle of the variable that reads the channel itself.
    const Variable x = *program.FindVariable("x");
    context.NextEvaluation();
    program.Evaluate(x, context);
    program.Evaluate(x, context);
    EXPECT_EQ(channels.reads[1], 3);
}

TEST(CalLanguage, ConstantDefinitionsFreezeAtFirstUse) {
    // §9.4 / §9.13 item 15: a `:` value that depends on the ray keeps its first
    // value and warns at every use.
    RtraceProgram rt;
    rt.program.LoadText("val = k + 1; k : Px*2;", "c.cal", "c");
    Channels channels;
    channels.values.assign(27, 0.0);
    std::vector<std::string> warnings;
    Context context(rt.program);
    context.SetChannels(&channels);
    context.SetWarnings([&](const std::string& m) { warnings.push_back(m); });
    const Variable val = *rt.program.FindVariable("val", "c");
    for (double px : {1.0, 3.0}) {
        channels.values[kPx - 1] = px;
        context.NextEvaluation();
        EXPECT_DOUBLE_EQ(rt.program.Evaluate(val, context), 3.0);
    }
    EXPECT_EQ(warnings, (std::vector<std::string>{"k`c: assigned non-constant value",
                                                  "k`c: assigned non-constant value"}));
}

TEST(CalLanguage, ConstantsAreFoldedAtParseTime) {
    Program program;
    program.LoadText("a : 2; b : a * 3 + sqrt(16); f(x) : x * b;", "k.cal");
    const Expression e = program.CompileExpression("f(2) + 1", "e");
    const Node& node = program.code().nodes[static_cast<std::size_t>(e.node)];
    EXPECT_EQ(node.op, Op::Num);
    EXPECT_DOUBLE_EQ(node.num, 21.0);
    // Not folded: a `=` function, or a ray quantity.
    program.LoadText("g(x) = x * 2;", "k.cal");
    const Expression e2 = program.CompileExpression("g(2)", "e");
    EXPECT_EQ(program.code().nodes[static_cast<std::size_t>(e2.node)].op, Op::Call);
}

TEST(CalLanguage, FunctionValuedArguments) {
    RtraceProgram rt;
    rt.program.LoadText("g(f, x) = f(x) * 2; h(t) = t + 1; k(f, x) = g(f, x) + 1;", "g.cal");
    Channels channels;
    channels.values.assign(27, 0.0);
    channels.values[kDx - 1] = 0.6;
    channels.values[kDz - 1] = -0.8;
    channels.values[kNz - 1] = 1.0;
    Context context(rt.program);
    context.SetChannels(&channels);
    context.NextEvaluation();
    EXPECT_DOUBLE_EQ(Eval(rt.program, "g(h, 2)", context), 6.0);
    EXPECT_DOUBLE_EQ(Eval(rt.program, "k(sqrt, 16)", context), 9.0);
    EXPECT_DOUBLE_EQ(Eval(rt.program, "dot(D, N)", context), -0.8);
    EXPECT_DOUBLE_EQ(Eval(rt.program, "cross(2, D, N)", context), -0.6);
}

TEST(CalLanguage, HandlesFollowRedefinition) {
    Program program;
    program.LoadText("x = 1; f(a) = a + x;", "a.cal");
    const Variable x = *program.FindVariable("x");
    const Function f = *program.FindFunction("f");
    EXPECT_FALSE(program.FindVariable("f").has_value());
    EXPECT_FALSE(program.FindFunction("x").has_value());
    EXPECT_FALSE(program.FindVariable("nosuch").has_value());
    EXPECT_EQ(program.Arity(f), 1);
    EXPECT_EQ(program.Arity(*program.FindFunction("atan2")), 2);
    Context context(program);
    context.NextEvaluation();
    const double one[] = {1.0};
    EXPECT_DOUBLE_EQ(program.Call(f, one, context), 2.0);
    program.LoadText("x = 5;", "b.cal");  // the context notices the reload
    context.NextEvaluation();
    EXPECT_DOUBLE_EQ(program.Evaluate(x, context), 5.0);
    EXPECT_DOUBLE_EQ(program.Call(f, one, context), 6.0);
    const double four[] = {4.0};
    EXPECT_DOUBLE_EQ(program.Call(*program.FindFunction("sqrt"), four, context), 2.0);
}

TEST(CalLanguage, ContextsKeepFilesApart) {
    // §9.13 item 14, with the files given as text in their contexts.
    RtraceProgram rt;
    rt.program.LoadText("v = 3; w = 1; w = 2; PI = 3; pa = Px*2;", "a.cal", "a");
    rt.program.LoadText("v = 5; usesA = pa;", "b.cal", "b");
    EXPECT_EQ(*rt.warnings, std::vector<std::string>{"w`a: redefined"});
    Context context(rt.program);
    context.NextEvaluation();
    EXPECT_DOUBLE_EQ(Eval(rt.program, "v*w", context, "a"), 6.0);
    EXPECT_DOUBLE_EQ(Eval(rt.program, "v", context, "b"), 5.0);
    EXPECT_NEAR(Eval(rt.program, "PI", context, "b"), M_PI, 1e-15);  // a's PI is a's own
    const Expression usesA = rt.program.CompileExpression("usesA", "brightfunc \"bf\"", "b");
    EXPECT_EQ(ErrorOf([&] { rt.program.Evaluate(usesA, context); }),
              "b.cal:1:16: undefined variable 'pa'");
}

TEST(CalLanguage, BackquoteForms) {
    // §9.13 item 17.
    RtraceProgram rt;
    rt.program.LoadText("PI = 3; q = PI` - PI; r = `PI;", "g.cal", "g");
    rt.program.LoadText("sin(x) = 5; v = sin(Px); floor(x) : 7;", "h.cal", "h");
    Channels channels;
    channels.values.assign(27, 0.0);
    channels.values[kPx - 1] = 1.0;
    Context context(rt.program);
    context.SetChannels(&channels);
    context.NextEvaluation();
    EXPECT_NEAR(Eval(rt.program, "q", context, "g"), 0.1415927, 5e-8);
    EXPECT_DOUBLE_EQ(Eval(rt.program, "r", context, "g"), 3.0);
    EXPECT_NEAR(Eval(rt.program, "PI`", context, "g"), M_PI, 1e-15);
    EXPECT_DOUBLE_EQ(Eval(rt.program, "v", context, "h"), 5.0);
    EXPECT_NEAR(Eval(rt.program, "sin(Px)+floor(0.5)", context), 0.841471, 5e-7);
}

TEST(CalLanguage, RedefinitionWarnings) {
    // §9.13 item 20: identical redefinitions (parameter names aside) are silent.
    RtraceProgram rt;
    rt.program.LoadText("w = 1; w = 1; x : 1; x : 2; val = w + x; f(a) = a; f(b) = b;", "c.cal",
                        "c");
    EXPECT_EQ(*rt.warnings, std::vector<std::string>{"x`c: redefined constant expression"});
    Context context(rt.program);
    context.NextEvaluation();
    EXPECT_DOUBLE_EQ(Eval(rt.program, "val", context, "c"), 3.0);
    rt.warnings->clear();
    rt.program.LoadText("sqrt(x) = x;", "s.cal");
    EXPECT_EQ(*rt.warnings, std::vector<std::string>{"sqrt: definition hides library function"});
}

TEST(CalLanguage, MathErrorsGiveZeroAndAFlag) {
    Program program;
    program.LoadText("v = 1 / $1;\nw = sqrt($1 - 1);", "m.cal");
    Channels channels;
    channels.values = {0.0};
    Context context(program);
    context.SetChannels(&channels);
    context.NextEvaluation();
    EXPECT_EQ(program.Evaluate(*program.FindVariable("v"), context), 0.0);
    EXPECT_EQ(context.mathError(), MathError::Range);
    EXPECT_EQ(context.mathErrorText(), "m.cal:1:7: Division by zero");
    context.NextEvaluation();
    EXPECT_EQ(context.mathError(), MathError::None);
    EXPECT_EQ(program.Evaluate(*program.FindVariable("w"), context), 0.0);
    EXPECT_EQ(context.mathError(), MathError::Domain);
    EXPECT_EQ(context.mathErrorText(), "m.cal:2:5: sqrt: domain error");
    channels.values = {4.0};
    context.NextEvaluation();
    EXPECT_DOUBLE_EQ(program.Evaluate(*program.FindVariable("v"), context), 0.25);
    EXPECT_EQ(context.mathError(), MathError::None);
}

// The error cases of the issue: each one line naming file, line and column.
TEST(CalErrors, SyntaxError) {
    Program program;
    EXPECT_EQ(ErrorOf([&] { program.LoadText("a = 1;\nb = (2 + ;", "x.cal"); }),
              "x.cal:2:10: unexpected character");
    EXPECT_EQ(ErrorOf([&] { program.LoadText("a = 1 {\n", "y.cal"); }), "y.cal:2:1: '}' expected");
    EXPECT_EQ(ErrorOf([&] { program.CompileExpression("2 3", "brightfunc \"b\""); }),
              "brightfunc \"b\":1:3: unexpected character");
}

TEST(CalErrors, UndefinedNames) {
    RtraceProgram rt;
    rt.program.LoadText("{ sky }\nv = 2 *\n    foo;\nw = bar(1);\nf(a) = a;\nu = f;", "sky.cal",
                        "sky");
    Context context(rt.program);
    context.NextEvaluation();
    const auto eval = [&](const char* name) {
        rt.program.Evaluate(*rt.program.FindVariable(name, "sky"), context);
    };
    EXPECT_EQ(ErrorOf([&] { eval("v"); }), "sky.cal:3:5: undefined variable 'foo'");
    EXPECT_EQ(ErrorOf([&] { eval("w"); }), "sky.cal:4:5: undefined function 'bar'");
    EXPECT_EQ(ErrorOf([&] { eval("u"); }), "sky.cal:6:5: undefined variable 'f'");
    EXPECT_EQ(ErrorOf([&] { Eval(rt.program, "E", context); }), "expr:1:1: undefined variable 'E'");
    EXPECT_EQ(ErrorOf([&] { Eval(rt.program, "j0(1)", context); }),
              "expr:1:1: undefined function 'j0'");
}

TEST(CalErrors, WrongArgumentCount) {
    Program program;
    program.LoadText("f(a, b) = a + b;\nv = 1 + f(1);\nw = f(1, 2, 3);\ng(a) = a(1);\nu = g(3);",
                     "n.cal");
    Context context(program);
    context.NextEvaluation();
    EXPECT_EQ(ErrorOf([&] { program.Evaluate(*program.FindVariable("v"), context); }),
              "n.cal:2:9: too few arguments to 'f'");
    EXPECT_DOUBLE_EQ(program.Evaluate(*program.FindVariable("w"), context), 3.0);
    EXPECT_EQ(ErrorOf([&] { program.Evaluate(*program.FindVariable("u"), context); }),
              "n.cal:4:8: argument not a function in 'g'");
    EXPECT_EQ(ErrorOf([&] { Eval(program, "atan2(1)", context); }),
              "expr:1:1: too few arguments to 'atan2'");
}

TEST(CalErrors, DivisionByZero) {
    Program program;
    EXPECT_EQ(ErrorOf([&] { program.LoadText("v = $1 / 0;", "d.cal"); }),
              "d.cal:1:10: divide by zero constant");
    EXPECT_EQ(ErrorOf([&] { program.LoadText("\n  v = 2 + 1/0;", "d.cal"); }),
              "d.cal:2:12: bad constant expression (Division by zero)");
    EXPECT_EQ(ErrorOf([&] { program.CompileExpression("if(1, $7, 1/0)", "brightfunc \"b\""); }),
              "brightfunc \"b\":1:12: bad constant expression (Division by zero)");
}

TEST(CalErrors, DeepRecursion) {
    Program program;
    program.LoadText("f(n) = f(n + 1) + 1;\nv = f(0);\nfact(n) = if(n - 1.5, n * fact(n - 1), 1);",
                     "r.cal");
    Context context(program);
    context.NextEvaluation();
    const std::string message =
        ErrorOf([&] { program.Evaluate(*program.FindVariable("v"), context); });
    EXPECT_TRUE(message.starts_with("r.cal:1:8: recursion too deep in 'f'")) << message;
    // The context stays usable, and legitimate recursion works.
    context.NextEvaluation();
    EXPECT_NEAR(Eval(program, "fact(150)", context), std::tgamma(151.0),
                1e-10 * std::tgamma(151.0));
}

TEST(CalErrors, DeepNestingIsASyntaxError) {
    Program program;
    const std::string deep = std::string(5000, '(') + "1" + std::string(5000, ')');
    EXPECT_NE(ErrorOf([&] {
                  program.CompileExpression(deep, "n.cal");
              }).find("expression too deeply nested"),
              std::string::npos);
    std::string chain = "x = 0";
    for (int i = 0; i < 3000; ++i) chain += " + y";
    EXPECT_NE(ErrorOf([&] { program.LoadText(chain, "n.cal"); }).find("too deeply nested"),
              std::string::npos);
    std::string power = "x = 2";
    for (int i = 0; i < 3000; ++i) power += "^y";
    EXPECT_NE(ErrorOf([&] { program.LoadText(power, "n.cal"); }).find("too deeply nested"),
              std::string::npos);
}

TEST(CalErrors, RayQuantitiesInConstants) {
    // §9.13 item 15: fatal at the reference that folds the constant.
    RtraceProgram rt;
    EXPECT_EQ(ErrorOf([&] { rt.program.LoadText("k : Px*2;\nval = k + 1;", "c.cal", "c"); }),
              "c.cal:2:7: ray parameter used in constant expression");
    EXPECT_EQ(ErrorOf([&] { rt.program.LoadText("c : A1;\nval = c*2;", "d.cal", "d"); }),
              "d.cal:2:7: bad call to arg(n) - illegal constant in .cal file?");
    Context context(rt.program);
    context.NextEvaluation();
    EXPECT_EQ(ErrorOf([&] { Eval(rt.program, "$28", context); }),
              "expr:1:1: illegal channel number $28");
}

TEST(CalThreads, ContextsPerThreadGiveTheSameAnswers) {
    RtraceProgram rt;
    rt.program.LoadText(
        "g = Acos(Dx*A2 + Dy*A3 + Dz*A4); v = (1 + exp(-3*g) + noise3(Dx*9, Dy*9, Dz*9))"
        " * if(Dz, 1, .5) + turbulence(Dx, Dy, Dz, .125);",
        "t.cal", "t");
    const Variable v = *rt.program.FindVariable("v", "t");
    const std::vector<double> args = {3.0, 0.0, 0.6, 0.8};
    const auto run = [&](std::vector<double>& out) {
        Context context(rt.program);
        Channels channels;
        channels.values.assign(27, 0.0);
        context.SetChannels(&channels);
        context.SetArguments(args, "brightfunc \"t\"");
        for (int i = 0; i < 2000; ++i) {
            const double a = 0.001 * i;
            channels.values[kDx - 1] = std::cos(a);
            channels.values[kDy - 1] = std::sin(a) * 0.6;
            channels.values[kDz - 1] = std::sin(a) * 0.8;
            context.NextEvaluation();
            out.push_back(rt.program.Evaluate(v, context));
        }
    };
    std::vector<double> serial, a, b;
    run(serial);
    std::thread ta([&] { run(a); });
    std::thread tb([&] { run(b); });
    ta.join();
    tb.join();
    EXPECT_EQ(a, serial);
    EXPECT_EQ(b, serial);
}

}  // namespace
}  // namespace rt::cal
