// SPDX-License-Identifier: MIT
//
// What rtrace adds around the language (radiance-functions.md §9.13 items
// 16-19, §10.3, §10.6 item 14): the ray variables, arg(n) and A1…, and
// lazyrad's own rayinit.cal evaluated with ray quantities. Values are the
// spec's, verified there with real rtrace (7 printed digits).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cal/ray_variables.h"
#include "tests/cal/cal_test_util.h"

namespace rt::cal {
namespace {

using testing::Channels;
using testing::ErrorOf;
using testing::RtraceProgram;

// The ray of §10.6 item 14: from (1,2,5) straight down onto the plane z = 0.
Channels DownwardRay() {
    Channels c;
    c.values.assign(kRayChannelCount, 0.0);
    c.values[kDz - 1] = -1.0;
    c.values[kNz - 1] = 1.0;
    c.values[kPx - 1] = 1.0;
    c.values[kPy - 1] = 2.0;
    c.values[kT - 1] = 5.0;
    c.values[kTs - 1] = 5.0;
    c.values[kRdot - 1] = 1.0;
    c.values[kS - 1] = 1.0;
    return c;
}

class RtraceCal : public ::testing::Test {
  protected:
    double Eval(const std::string& expr, const std::string& ctx = {}) {
        const Expression e = rt_.program.CompileExpression(expr, "colorfunc \"cf\"", ctx);
        return rt_.program.Evaluate(e, context_);
    }
    void SetUp() override {
        context_.SetChannels(&ray_);
        context_.NextEvaluation();
    }
    RtraceProgram rt_;
    Channels ray_ = DownwardRay();
    Context context_{rt_.program};
};

TEST_F(RtraceCal, RayVariablesAreChannels) {
    for (int n = 1; n <= kRayChannelCount; ++n) {
        ray_.values[static_cast<std::size_t>(n - 1)] = 100.0 + n;
    }
    context_.NextEvaluation();
    for (int n = 1; n <= kRayChannelCount; ++n) {
        const std::string name = kRayVariableNames[static_cast<std::size_t>(n - 1)];
        EXPECT_DOUBLE_EQ(Eval(name), 100.0 + n) << name;
        std::string channel = "$";
        channel += std::to_string(n);
        EXPECT_DOUBLE_EQ(Eval(channel), 100.0 + n) << n;
    }
}

TEST_F(RtraceCal, Rayinit10_6Item14) {
    EXPECT_DOUBLE_EQ(Eval("select(2,U,V,1)"), 2.0);
    EXPECT_DOUBLE_EQ(Eval("U"), 1.0);
    EXPECT_DOUBLE_EQ(Eval("V"), 2.0);
    EXPECT_DOUBLE_EQ(Eval("dot(D,N)"), -1.0);
    EXPECT_DOUBLE_EQ(Eval("cross(1,D,N)"), 0.0);
    EXPECT_DOUBLE_EQ(Eval("noop(4)"), 4.0);
    EXPECT_NEAR(Eval("turbulence(1.3,2.7,-0.4,0.25)"), 0.4588283, 5e-8);
    EXPECT_NEAR(Eval("DEGREE"), 0.01745329, 5e-9);
    EXPECT_DOUBLE_EQ(Eval("FTINY"), 1e-7);
    EXPECT_NEAR(Eval("unif2norm(0.975)"), 1.960395, 5e-7);
    EXPECT_NEAR(Eval("unif2norm(0.5)"), -1.010067e-07, 5e-14);
    EXPECT_DOUBLE_EQ(Eval("Lu + Lv + arg(0)"), 0.0);
}

TEST_F(RtraceCal, PlanarCoordinatesOnATiltedSurface) {
    // A normal off the z axis: U, V are the in-plane coordinates of §10.5.
    ray_.values[kNx - 1] = 0.6;
    ray_.values[kNy - 1] = 0.0;
    ray_.values[kNz - 1] = 0.8;
    ray_.values[kPx - 1] = 1.0;
    ray_.values[kPy - 1] = 2.0;
    ray_.values[kPz - 1] = 3.0;
    context_.NextEvaluation();
    EXPECT_DOUBLE_EQ(Eval("U"), (2.0 * 0.6 - 1.0 * 0.0) / 0.36);
    EXPECT_DOUBLE_EQ(Eval("V"), 3.0 - 0.8 * (1.0 * 0.6) / 0.36);
}

TEST_F(RtraceCal, RealArguments9_13Item16) {
    const std::vector<double> args = {10.0, 20.0};
    context_.SetArguments(args, "brightfunc \"bf\"");
    EXPECT_DOUBLE_EQ(Eval("A1 + arg(0) + AC"), 14.0);
    EXPECT_DOUBLE_EQ(Eval("arg(-5) + arg(2.4)"), 22.0);
    EXPECT_DOUBLE_EQ(Eval("arg(0.4) + arg(1.49) + A2"), 2.0 + 10.0 + 20.0);
    EXPECT_EQ(ErrorOf([&] { Eval("A3"); }),
              "rayinit.cal:20:32: missing real argument 3 for brightfunc \"bf\"");
    EXPECT_EQ(ErrorOf([&] { Eval("1 + arg(7)"); }),
              "colorfunc \"cf\":1:5: missing real argument 7 for brightfunc \"bf\"");
}

TEST_F(RtraceCal, ArgumentsAndRayInOneFile9_13Item15) {
    rt_.program.LoadText("val = c*2; c = A1 + Px;", "c.cal", "c");
    const std::vector<double> args = {10.0, 20.0};
    context_.SetArguments(args, "brightfunc \"bf\"");
    const Variable val = *rt_.program.FindVariable("val", "c");
    ray_.values[kPx - 1] = 1.0;
    context_.NextEvaluation();
    EXPECT_DOUBLE_EQ(rt_.program.Evaluate(val, context_), 22.0);
    ray_.values[kPx - 1] = 7.0;
    context_.NextEvaluation();
    EXPECT_DOUBLE_EQ(rt_.program.Evaluate(val, context_), 34.0);
}

TEST_F(RtraceCal, GlobalNames9_13Item18) {
    EXPECT_DOUBLE_EQ(Eval("abs(-1)"), 1.0);
    EXPECT_NEAR(Eval("erf(0.5)"), 0.5204999, 5e-8);
    EXPECT_NEAR(Eval("erfc(0.5)"), 0.4795001, 5e-8);
    EXPECT_NE(ErrorOf([&] { Eval("E"); }).find("undefined variable 'E'"), std::string::npos);
    EXPECT_NE(ErrorOf([&] { Eval("j0(1)"); }).find("undefined function 'j0'"), std::string::npos);
}

TEST_F(RtraceCal, Noise9_13Item19) {
    EXPECT_DOUBLE_EQ(Eval("noise3(0.5,0.5,0.5)"), -0.25);
    EXPECT_NEAR(Eval("noise3(1.3,2.7,-0.4)"), -0.1102238, 5e-8);
    EXPECT_NEAR(Eval("noise3(-7.25,100.5,3.125)"), 0.4606968, 5e-8);
    EXPECT_EQ(Eval("noise3(1,2,3)"), 0.0);
    EXPECT_NEAR(Eval("noise3x(1.3,2.7,-0.4)"), -0.8394579, 5e-8);
    EXPECT_NEAR(Eval("noise3y(1.3,2.7,-0.4)"), -1.161965, 5e-7);
    EXPECT_NEAR(Eval("noise3z(1.3,2.7,-0.4)"), 0.3905239, 5e-8);
    EXPECT_NEAR(Eval("noise3a(1.3,2.7,-0.4) + noise3d(2,1.3,2.7,-0.4)"), -0.8394579 - 1.161965,
                5e-7);
    EXPECT_NEAR(Eval("fnoise3(0.5,0.5,0.5)"), -0.3412551, 5e-8);
    EXPECT_NEAR(Eval("fnoise3(1.3,2.7,-0.4)"), -0.07206283, 5e-9);
    EXPECT_NEAR(Eval("fnoise3(-7.25,100.5,3.125)"), 0.5449893, 5e-8);
}

TEST(RtraceSetup, MissingRayinitIsASystemError) {
    Program program;
    SearchPath nowhere;
    nowhere.builtins = false;
    try {
        program.LoadRayinit(nowhere);
        FAIL() << "expected rt::Error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "cannot find function file \"rayinit.cal\"");
        EXPECT_EQ(e.ExitCode(), 2);
    }
}

}  // namespace
}  // namespace rt::cal
