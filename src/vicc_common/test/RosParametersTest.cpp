#include <gtest/gtest.h>
#include <ros/ros.h>

#include "test_config.hpp"
#include "vicc_common/parameter_names.hpp"
#include "vicc_common/ros_parameters.hpp"

namespace vicc_common_test {
namespace {

using vicc_common::readRosParameters;

/// Reads the table from the test node's private sub-namespace `ns`.
Outer readFrom(const std::string& ns, std::set<std::string>& read_names) {
  Outer config;
  readRosParameters(ros::NodeHandle("~" + ns), config, read_names);
  return config;
}

std::string errorOf(const std::string& ns) {
  std::set<std::string> read_names;
  try {
    readFrom(ns, read_names);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

std::string privateName(const std::string& name) { return ros::NodeHandle("~").resolveName(name); }

TEST(RosParameters, ReadsEveryTypeIntoTheTable) {
  std::set<std::string> read_names;
  const Outer config = readFrom("good", read_names);
  EXPECT_EQ(config.count, 7);
  EXPECT_TRUE(config.enabled);
  EXPECT_EQ(config.name, "probe");
  EXPECT_EQ(config.weights, (std::vector<double>{1.5, 2.0}));
  EXPECT_EQ(config.shape, Shape::kSquare);
  EXPECT_DOUBLE_EQ(config.inner.gain, 2.0);  // an integer is a valid number
  EXPECT_EQ(config.inner.levels, (std::vector<int>{8}));
  EXPECT_EQ(read_names.count(privateName("good/inner/levels")), 1u);
}

TEST(RosParameters, KeysLeftOutKeepTheirDefaults) {
  std::set<std::string> read_names;
  const Outer config = readFrom("absent", read_names);
  EXPECT_EQ(config.count, 3);
  EXPECT_EQ(config.name, "default");
  EXPECT_EQ(read_names.size(), 7u);  // every key of the table was asked for
}

TEST(RosParameters, WrongTypesNameTheParameterAndTheExpectedType) {
  EXPECT_EQ(errorOf("wrong_int"), "parameter " + privateName("wrong_int/count") +
                                      " has the wrong type: expected an integer, got 'many'");
  // roscpp's getParam(int&) would round 2.5 to 3 and accept it.
  EXPECT_EQ(errorOf("fractional_int"), "parameter " + privateName("fractional_int/count") +
                                           " has the wrong type: expected an integer, got '2.5'");
  EXPECT_EQ(errorOf("wrong_double"), "parameter " + privateName("wrong_double/inner/gain") +
                                         " has the wrong type: expected a number, got 'fast'");
  EXPECT_EQ(errorOf("wrong_list"), "parameter " + privateName("wrong_list/inner/levels") +
                                       " has the wrong type: expected a list of integers, got '3'");
  EXPECT_EQ(errorOf("wrong_bool"), "parameter " + privateName("wrong_bool/enabled") +
                                       " has the wrong type: expected true or false, got '1'");
}

TEST(RosParameters, TextValuesAndValidateNameWhereTheyFailed) {
  EXPECT_EQ(errorOf("bad_shape"), "parameter " + privateName("bad_shape/shape") +
                                      ": unknown shape 'hexagon' (circle or square)");
  EXPECT_EQ(errorOf("invalid"),
            "parameters under " + privateName("invalid/inner") + ": gain must be > 0");
}

TEST(RosParameters, UnknownParametersInTheNamespaceAreNamed) {
  std::set<std::string> read_names;
  const ros::NodeHandle typo_nh("~typo");
  readFrom("typo", read_names);
  const std::vector<std::string> unknown =
      vicc_common::warnUnknownRosParameters(typo_nh, read_names);
  EXPECT_EQ(unknown,
            (std::vector<std::string>{privateName("typo/cuont"), privateName("typo/inner/gian")}));
  std::set<std::string> good_names;
  readFrom("good", good_names);
  EXPECT_TRUE(vicc_common::unknownRosParameters(ros::NodeHandle("~good"), good_names).empty());
  // Another library's namespace under the node's (an image_transport publisher's) is its own.
  EXPECT_EQ(vicc_common::unknownRosParameters(typo_nh, read_names, {privateName("typo/inner")}),
            std::vector<std::string>{privateName("typo/cuont")});
}

}  // namespace
}  // namespace vicc_common_test

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "ros_parameters_test");
  ros::NodeHandle nh;  // starts the node so the parameter server can be queried
  return RUN_ALL_TESTS();
}
