// SPDX-License-Identifier: MIT
#include "view/view.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "core/error.h"

namespace rt {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

std::string ErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "<no error>";
}

double AngleBetween(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(Dot(a, b) / (Length(a) * Length(b)), -1.0, 1.0));
}

void ExpectVecNear(const Vec3& a, const Vec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

View MakeView(ViewType type, double vh, double vv) {
    View v;
    v.type = type;
    v.vp = {1, 2, 3};
    v.vd = {0, 2, 0};  // not unit on purpose
    v.vu = {0, 0, 1};
    v.vh = vh;
    v.vv = vv;
    return v;
}

TEST(ViewParse, EachOption) {
    const View v = ParseViewArgs({"-vta", "-vp", "1",  "2",   "3",   "-vd", "0",   "-1",  "0.5",
                                  "-vu",  "0",   "1",  "0",   "-vh", "180", "-vv", "120", "-vo",
                                  "0.25", "-va", "10", "-vs", "0.1", "-vl", "-0.2"});
    EXPECT_EQ(v.type, ViewType::Angular);
    EXPECT_EQ(v.vp, Vec3(1, 2, 3));
    EXPECT_EQ(v.vd, Vec3(0, -1, 0.5));
    EXPECT_EQ(v.vu, Vec3(0, 1, 0));
    EXPECT_EQ(v.vh, 180);
    EXPECT_EQ(v.vv, 120);
    EXPECT_EQ(v.vo, 0.25);
    EXPECT_EQ(v.va, 10);
    EXPECT_EQ(v.vs, 0.1);
    EXPECT_EQ(v.vl, -0.2);
    for (const char* t : {"-vtv", "-vtl", "-vta", "-vth", "-vts", "-vtc"}) {
        EXPECT_EQ(static_cast<char>(ParseViewArgs({t}).type), t[3]);
    }
    // Defaults are Radiance's STDVIEW.
    const View d;
    EXPECT_EQ(d.type, ViewType::Perspective);
    EXPECT_EQ(d.vd, Vec3(0, 1, 0));
    EXPECT_EQ(d.vh, 45);
}

TEST(ViewParse, OptionReturnsWordsUsedOrNothing) {
    View v;
    const std::vector<std::string> args = {"-vh", "30", "-x", "5"};
    EXPECT_EQ(ParseViewOption(v, std::span(args)), 1);
    EXPECT_EQ(ParseViewOption(v, std::span(args).subspan(2)), std::nullopt);
    EXPECT_EQ(v.vh, 30);
}

TEST(ViewParse, ErrorsNameTheOption) {
    EXPECT_NE(ErrorOf([] {
                  (void)ParseViewArgs({"-vp", "1", "2"});
              }).find("-vp"),
              std::string::npos);
    EXPECT_NE(ErrorOf([] {
                  (void)ParseViewArgs({"-vh", "wide"});
              }).find("'wide'"),
              std::string::npos);
    EXPECT_NE(ErrorOf([] { (void)ParseViewArgs({"-vtx"}); }).find("unknown view type 'x'"),
              std::string::npos);
    EXPECT_NE(ErrorOf([] { (void)ParseViewArgs({"-vt"}); }).find("-vt"), std::string::npos);
    EXPECT_NE(ErrorOf([] { (void)ParseViewArgs({"-vz", "1"}); }).find("-vz"), std::string::npos);
    EXPECT_NE(ErrorOf([] {
                  (void)ParseViewArgs({"-vf", "/nonexistent/x.vf"});
              }).find("/nonexistent/x.vf"),
              std::string::npos);
    EXPECT_NE(ErrorOf([] { (void)ParseViewArgs({"-vf"}); }).find("-vf"), std::string::npos);
}

TEST(ViewParse, ScanViewStringLikeSscanview) {
    View v;
    EXPECT_EQ(ScanViewString(v, "rview -vtl -vp 1 2 3 -vh 10 junk -vv 5\n"), 4);
    EXPECT_EQ(v.type, ViewType::Parallel);
    EXPECT_EQ(v.vp, Vec3(1, 2, 3));
    EXPECT_EQ(v.vh, 10);
    EXPECT_EQ(v.vv, 5);
    View w;
    EXPECT_EQ(ScanViewString(w, "VIEW= -vth -vd 1 0 0 -vp 1 x 3"), 2);  // bad -vp skipped
    EXPECT_EQ(w.type, ViewType::Hemispherical);
    EXPECT_EQ(w.vd, Vec3(1, 0, 0));
    EXPECT_EQ(w.vp, Vec3(0, 0, 0));
    EXPECT_TRUE(IsViewLine("rview -vtv"));
    EXPECT_TRUE(IsViewLine("/usr/local/bin/rpict -vtv"));
    EXPECT_TRUE(IsViewLine("VIEW= -vtv"));
    EXPECT_FALSE(IsViewLine("rtrace -ab 2"));
}

TEST(ViewParse, ReadsSceneViewFiles) {
    const View cornell =
        ParseViewArgs({"-vf", std::string(RT_SOURCE_DIR) + "/scenes/cornell/cornell.vf"});
    EXPECT_EQ(cornell.type, ViewType::Perspective);
    EXPECT_EQ(cornell.vp, Vec3(2.78, -8.0, 2.74));
    EXPECT_EQ(cornell.vd, Vec3(0, 1, 0));
    EXPECT_EQ(cornell.vh, 39);
    EXPECT_EQ(cornell.vv, 39);
    // Later options override the file, as in Radiance.
    const View room = ParseViewArgs(
        {"-vf", std::string(RT_SOURCE_DIR) + "/scenes/daylit_room/daylit_room.vf", "-vh", "60"});
    EXPECT_EQ(room.vp, Vec3(2, 5.8, 1.5));
    EXPECT_EQ(room.vd, Vec3(0, -1, -0.15));
    EXPECT_EQ(room.vv, 55);
    EXPECT_EQ(room.vh, 60);
}

TEST(ViewParse, ViewFileWithoutViewIsAnError) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("lazyrad_noview_" + std::to_string(::getpid()) + ".vf"))
                                 .string();
    std::ofstream(path) << "# nothing here\nrtrace -ab 1\n";
    const std::string message = ErrorOf([&] { (void)ParseViewArgs({"-vf", path}); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("no view"), std::string::npos) << message;
    // A picture header: VIEW= line, then a blank line and binary data that is not read.
    std::ofstream(path) << "#?RADIANCE\nrpict -vtv\nVIEW= -vta -vh 180 -vv 180\n"
                           "FORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n\x80\x80\x80\x81";
    View v;
    ReadViewFile(path, v);
    EXPECT_EQ(v.type, ViewType::Angular);
    EXPECT_EQ(v.vh, 180);
    std::filesystem::remove(path);
}

TEST(SetupView, RejectsBadViewsWithRadianceMessages) {
    auto bad = [](View v) { return ErrorOf([&] { (void)SetupView(v); }); };
    View v;
    v.vd = {0, 0, 0};
    EXPECT_NE(bad(v).find("zero view direction"), std::string::npos);
    v = View();
    v.vu = {0, 0, 0};
    EXPECT_NE(bad(v).find("zero view up vector"), std::string::npos);
    v = View();
    v.vu = {0, -3, 0};
    EXPECT_NE(bad(v).find("view up parallel to view direction"), std::string::npos);
    v = View();
    v.vh = 180;
    EXPECT_NE(bad(v).find("illegal horizontal view size"), std::string::npos);
    v = View();
    v.vv = 0;
    EXPECT_NE(bad(v).find("illegal vertical view size"), std::string::npos);
    v = View();
    v.va = 1;
    v.vo = 2;
    EXPECT_NE(bad(v).find("illegal fore/aft clipping plane"), std::string::npos);
    EXPECT_NE(bad(MakeView(ViewType::Hemispherical, 181, 90)).find("horizontal"),
              std::string::npos);
    EXPECT_NE(bad(MakeView(ViewType::Angular, 90, 361)).find("vertical"), std::string::npos);
    EXPECT_NE(bad(MakeView(ViewType::Planisphere, 360, 90)).find("horizontal"), std::string::npos);
    EXPECT_NE(bad(MakeView(ViewType::Cylindrical, 360, 180)).find("vertical"), std::string::npos);
    EXPECT_NO_THROW((void)SetupView(MakeView(ViewType::Cylindrical, 360, 90)));
    EXPECT_NO_THROW((void)SetupView(MakeView(ViewType::Parallel, 500, 300)));
}

// The centre ray is the view direction for every projection, and rays mirror
// about the centre lines.
TEST(ViewRay, CentreIsViewDirectionAndRaysAreSymmetric) {
    for (ViewType t : {ViewType::Perspective, ViewType::Parallel, ViewType::Angular,
                       ViewType::Hemispherical, ViewType::Planisphere, ViewType::Cylindrical}) {
        SCOPED_TRACE(std::string(1, static_cast<char>(t)));
        const PreparedView pv = SetupView(MakeView(t, 60, 40));
        const auto c = ViewRay(pv, 0.5, 0.5);
        ASSERT_TRUE(c);
        ExpectVecNear(c->direction, {0, 1, 0});
        ExpectVecNear(c->origin, {1, 2, 3});
        const auto l = ViewRay(pv, 0.2, 0.7);
        const auto r = ViewRay(pv, 0.8, 0.7);
        const auto d = ViewRay(pv, 0.2, 0.3);
        ASSERT_TRUE(l && r && d);
        EXPECT_NEAR(Length(l->direction), 1.0, 1e-12);
        // hvec is +x here (vd × vu = y × z), vvec is +z. A parallel view moves
        // the origin instead of turning the direction.
        const bool parallel = t == ViewType::Parallel;
        const Vec3 lv = parallel ? l->origin - Vec3(1, 2, 3) : l->direction;
        const Vec3 rv = parallel ? r->origin - Vec3(1, 2, 3) : r->direction;
        const Vec3 dv = parallel ? d->origin - Vec3(1, 2, 3) : d->direction;
        ExpectVecNear(rv, {-lv.x, lv.y, lv.z});
        ExpectVecNear(dv, {lv.x, lv.y, -lv.z});
        EXPECT_LT(lv.x, 0.0);
        EXPECT_GT(lv.z, 0.0);
    }
}

TEST(ViewRay, PerspectiveEdgesAreAtHalfTheViewAngles) {
    const PreparedView pv = SetupView(MakeView(ViewType::Perspective, 60, 40));
    EXPECT_NEAR(AngleBetween(ViewRay(pv, 1.0, 0.5)->direction, {0, 1, 0}), 30 * kDeg, 1e-12);
    EXPECT_NEAR(AngleBetween(ViewRay(pv, 0.5, 0.0)->direction, {0, 1, 0}), 20 * kDeg, 1e-12);
    // Hand-computed: corner (1,1) direction ∝ vd + ½·2tan30°·h + ½·2tan20°·v.
    ExpectVecNear(ViewRay(pv, 1, 1)->direction,
                  Normalize(Vec3(std::tan(30 * kDeg), 1, std::tan(20 * kDeg))));
}

TEST(ViewRay, CornellFirstPixelMatchesRadiance) {
    // First line of scenes/cornell/cam32.rays (Radiance's vwrays -x 32 -y 32).
    const PreparedView pv =
        SetupView(ParseViewArgs({"-vtv", "-vp", "2.78", "-8.0", "2.74", "-vd", "0", "1", "0", "-vu",
                                 "0", "0", "1", "-vh", "39", "-vv", "39"}));
    const auto ray = ViewRay(pv, 0.5 / 32, 31.5 / 32);
    ExpectVecNear(ray->direction, {-3.08647e-01, 8.99708e-01, 3.08647e-01}, 1e-6);
}

TEST(ViewRay, ParallelOffsetsOriginByHalfTheSize) {
    const PreparedView pv = SetupView(MakeView(ViewType::Parallel, 6, 4));
    const auto r = ViewRay(pv, 1.0, 0.0);
    ExpectVecNear(r->origin, {1 + 3, 2, 3 - 2});
    ExpectVecNear(r->direction, {0, 1, 0});
}

TEST(ViewRay, AngularFisheyeMapsRadiusToAngle) {
    const PreparedView pv = SetupView(MakeView(ViewType::Angular, 180, 180));
    for (double dx : {0.05, 0.2, 0.35, 0.5}) {
        // Radius dx of the unit image is dx·vh degrees off axis.
        EXPECT_NEAR(AngleBetween(ViewRay(pv, 0.5 + dx, 0.5)->direction, {0, 1, 0}), dx * 180 * kDeg,
                    1e-12);
        const double diag = dx / std::sqrt(2.0);
        EXPECT_NEAR(AngleBetween(ViewRay(pv, 0.5 + diag, 0.5 - diag)->direction, {0, 1, 0}),
                    dx * 180 * kDeg, 1e-12);
    }
    // At 180° the image circle (radius 1 at 360°) still covers the corners,
    // which look more than 90° off axis, as in Radiance.
    ASSERT_TRUE(ViewRay(pv, 1.0, 1.0));
    EXPECT_NEAR(AngleBetween(ViewRay(pv, 1.0, 1.0)->direction, {0, 1, 0}), std::sqrt(0.5) * kPi,
                1e-12);
    const PreparedView full = SetupView(MakeView(ViewType::Angular, 360, 360));
    EXPECT_FALSE(ViewRay(full, 0.95, 0.95));  // outside the 360° circle
    ExpectVecNear(ViewRay(full, 1.0, 0.5)->direction, {0, -1, 0}, 1e-12);  // straight back
}

TEST(ViewRay, HemisphericalAndPlanisphereEdgesAreAtHalfTheViewAngle) {
    const PreparedView hem = SetupView(MakeView(ViewType::Hemispherical, 180, 120));
    EXPECT_NEAR(AngleBetween(ViewRay(hem, 1.0, 0.5)->direction, {0, 1, 0}), 90 * kDeg, 1e-7);
    EXPECT_NEAR(AngleBetween(ViewRay(hem, 0.5, 1.0)->direction, {0, 1, 0}), 60 * kDeg, 1e-12);
    // Hemispherical: image radius ∝ sin(angle).
    EXPECT_NEAR(std::sin(AngleBetween(ViewRay(hem, 0.75, 0.5)->direction, {0, 1, 0})), 0.5, 1e-12);
    EXPECT_FALSE(ViewRay(hem, 1.0, 1.0));

    const PreparedView pls = SetupView(MakeView(ViewType::Planisphere, 180, 180));
    EXPECT_NEAR(AngleBetween(ViewRay(pls, 1.0, 0.5)->direction, {0, 1, 0}), 90 * kDeg, 1e-12);
    // Stereographic: image radius ∝ tan(angle/2); half the radius → tan(θ/2) = tan(45°)/2.
    EXPECT_NEAR(AngleBetween(ViewRay(pls, 0.75, 0.5)->direction, {0, 1, 0}), 2 * std::atan(0.5),
                1e-12);
    ASSERT_TRUE(ViewRay(pls, 1.0, 1.0));  // planisphere has no outside
}

TEST(ViewRay, CylindricalIsLinearInAzimuthAndPerspectiveVertically) {
    const PreparedView pv = SetupView(MakeView(ViewType::Cylindrical, 360, 90));
    const Vec3 back = ViewRay(pv, 0.0, 0.5)->direction;
    ExpectVecNear(back, {0, -1, 0});
    const Vec3 right = ViewRay(pv, 0.75, 0.5)->direction;
    ExpectVecNear(right, {1, 0, 0});
    const Vec3 up = ViewRay(pv, 0.75, 1.0)->direction;
    EXPECT_NEAR(std::atan2(up.z, up.x), 45 * kDeg, 1e-12);
}

TEST(ViewRay, ShiftLiftAndClipping) {
    View v = MakeView(ViewType::Perspective, 60, 40);
    const PreparedView plain = SetupView(v);
    v.vs = 0.5;
    v.vl = -0.25;
    v.vo = 2;
    v.va = 5;
    const PreparedView shifted = SetupView(v);
    const auto a = ViewRay(shifted, 0.5, 0.5);
    const auto b = ViewRay(plain, 1.0, 0.25);
    ExpectVecNear(a->direction, b->direction);
    // Origin moves to the fore plane along the unnormalised direction; the aft
    // distance is scaled the same way.
    const double len = 1.0 / Dot(a->direction, Vec3(0, 1, 0));
    ExpectVecNear(a->origin, Vec3(1, 2, 3) + 2 * len * a->direction, 1e-12);
    EXPECT_NEAR(a->maxDistance, 3 * len, 1e-12);
    EXPECT_EQ(ViewRay(plain, 0.5, 0.5)->maxDistance, 0.0);
}

TEST(ViewAspect, NormalizeAspectReducesOneResolution) {
    const PreparedView pv = SetupView(ParseViewArgs({"-vh", "70", "-vv", "55"}));
    double pa = 1;
    int x = 32, y = 32;
    NormalizeAspect(ViewAspect(pv), pa, x, y);
    EXPECT_EQ(x, 32);
    EXPECT_EQ(y, 24);
    pa = 0;
    x = 100;
    y = 50;
    NormalizeAspect(1.0, pa, x, y);
    EXPECT_EQ(pa, 2.0);
    EXPECT_EQ(x, 100);
}

TEST(FormatView, WritesEveryParameter) {
    EXPECT_EQ(FormatView(View()),
              " -vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0 -vl 0");
    View v = ParseViewArgs({"-vta", "-vh", "180"});
    View back;
    EXPECT_EQ(ScanViewString(back, "VIEW=" + FormatView(v)), 10);
    EXPECT_EQ(back, v);
}

}  // namespace
}  // namespace rt
