#include <gtest/gtest.h>

#include <cmath>

#include "vicc_glyphs/perception/perception_model.hpp"

using vicc_glyphs::perception::levelForValue;

TEST(LevelForValue, EqualBinsWithTheUpperEdgeInTheLastLevel) {
  EXPECT_EQ(levelForValue(0.0, 0.0, 1.0, 4), 0);
  EXPECT_EQ(levelForValue(0.2499, 0.0, 1.0, 4), 0);
  EXPECT_EQ(levelForValue(0.25, 0.0, 1.0, 4), 1);
  EXPECT_EQ(levelForValue(0.74, 0.0, 1.0, 4), 2);
  EXPECT_EQ(levelForValue(1.0, 0.0, 1.0, 4), 3);
  EXPECT_EQ(levelForValue(15.0, 10.0, 20.0, 1), 0);
}

TEST(LevelForValue, NanAndOutOfDomainNameTheValue) {
  try {
    levelForValue(std::nan(""), 0.0, 1.0, 4, "probability");
    FAIL();
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("probability is NaN"), std::string::npos);
  }
  try {
    levelForValue(1.5, 0.0, 1.0, 4, "probability");
    FAIL();
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("probability = 1.5"), std::string::npos);
  }
  EXPECT_THROW(levelForValue(-0.01, 0.0, 1.0, 4), std::domain_error);
  EXPECT_THROW(levelForValue(0.5, 1.0, 1.0, 4), std::invalid_argument);
  EXPECT_THROW(levelForValue(0.5, 0.0, 1.0, 0), std::invalid_argument);
}
