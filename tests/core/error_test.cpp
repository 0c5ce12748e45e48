#include "core/error.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Error, MessageNamesFileAndLine) {
    Error e(Error::Kind::User, FileLoc{"room.rad", 12}, "undefined modifier \"x\"");
    EXPECT_STREQ(e.what(), "room.rad:12: undefined modifier \"x\"");
    EXPECT_EQ(e.ExitCode(), 1);
}

TEST(Error, BinaryLocationsUseByteOffsets) {
    Error e(Error::Kind::System, FileLoc{"a.amb", 0, 134}, "bad record");
    EXPECT_STREQ(e.what(), "a.amb: byte 134: bad record");
    EXPECT_EQ(e.ExitCode(), 2);
}

// Radiance's internal-kind reports of bad input keep its word and status but
// refuse the input; lazyrad's own internal errors do not (the fuzz rule).
TEST(Error, InternalByInputKeepsRadiancesStatusButRefusesTheInput) {
    const Error mine(Error::Kind::Internal, "data array of inconsistent size");
    EXPECT_FALSE(mine.RefusesInput());
    const Error radiances = Error::InternalByInput(FileLoc{"fog.rad", 3}, "too many sources");
    EXPECT_EQ(radiances.kind(), Error::Kind::Internal);
    EXPECT_EQ(radiances.ExitCode(), 3);
    EXPECT_STREQ(radiances.what(), "fog.rad:3: too many sources");
    EXPECT_TRUE(radiances.RefusesInput());
    EXPECT_TRUE(Error::InternalByInput("overflow").RefusesInput());
    EXPECT_TRUE(Error(Error::Kind::User, "x").RefusesInput());
    EXPECT_TRUE(Error(Error::Kind::System, "x").RefusesInput());
}

}  // namespace
}  // namespace rt
