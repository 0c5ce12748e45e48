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

}  // namespace
}  // namespace rt
