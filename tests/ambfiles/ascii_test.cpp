// SPDX-License-Identifier: MIT
#include "ambfiles/ascii.h"

#include <gtest/gtest.h>

#include "ambfiles/record_codec.h"

namespace rt {
namespace {

AmbientRecord Sample() {
    AmbientRecord r;
    r.position = {2, 2, 0};
    r.normal = {0, 0, 1};
    r.uAxis = {-0.578445, -0.815721, 0};
    r.value = Rgb::Grey(0.529297);
    r.radius[0] = r.radius[1] = 0.800004;
    r.posGradient[0] = -0.009374;
    r.posGradient[1] = -0.003547;
    r.dirGradient[0] = 0.012898;
    r.dirGradient[1] = 0.005010;
    r.weight = 1;
    r.corral = 0xbeef;
    return *DecodeRecord(EncodeRecord(r));
}

TEST(AmbientText, DataOnlyLineMatchesLookamb) {
    AmbientRecord r = Sample();
    r.corral = 0;
    // radiance-notes.md §5.2: lookamb -d -h of the worked example.
    EXPECT_EQ(FormatAmbientText(r, AmbientTextLayout::DataOnly),
              "2.000000\t2.000000\t0.000000\t0.000000\t0.000000\t1.000000\t-0.578445\t-0.815721\t"
              "0.000000\t0\t1.000000\t0.800004\t0.800004\t5.292969e-01\t5.292969e-01\t"
              "5.292969e-01\t-0.009374\t-0.003547\t0.012898\t0.005010\t0\n");
}

TEST(AmbientText, LabelledLayout) {
    EXPECT_EQ(FormatAmbientText(Sample(), AmbientTextLayout::Labelled),
              "Position:\t2.000000\t2.000000\t0.000000\n"
              "Normal:\t\t0.000000\t0.000000\t1.000000\n"
              "Uvector:\t-0.578445\t-0.815721\t0.000000\n"
              "Lvl,Wt,UVrad:\t0\t\t1.000000\t0.800004\t0.800004\n"
              "Value:\t\t5.292969e-01\t5.292969e-01\t5.292969e-01\n"
              "Pos.Grad:\t-0.009374\t-0.003547\n"
              "Dir.Grad:\t0.012898\t0.005010\n"
              "Corral:\t\t    BEEF\n\n");
}

TEST(AmbientText, BothLayoutsParseBack) {
    for (auto layout : {AmbientTextLayout::DataOnly, AmbientTextLayout::Labelled}) {
        const AmbientRecord r = Sample();
        const std::string text = FormatAmbientText(r, layout) + FormatAmbientText(r, layout);
        const auto parsed = ParseAmbientText(text, layout);
        ASSERT_EQ(parsed.size(), 2u);
        EXPECT_EQ(EncodeRecord(parsed[1]), EncodeRecord(r));
        // A cut-off record ends reading silently.
        EXPECT_EQ(ParseAmbientText(text.substr(0, text.size() - 12), layout).size(), 1u);
    }
}

}  // namespace
}  // namespace rt
