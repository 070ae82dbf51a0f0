#include <gtest/gtest.h>
TEST(CliSmoke, Builds) { EXPECT_EQ(1, 1); }
