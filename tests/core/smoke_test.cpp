#include "core/swp_parser.hpp"

#include <gtest/gtest.h>

TEST(Smoke, EmptyFileIsAnEmptyDocument) { EXPECT_TRUE(sweep::parse_swp("", "empty.swp").objects.empty()); }
