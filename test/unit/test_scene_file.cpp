#include "vofdem/base/SceneFile.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

std::string WriteTemp(const std::string &name, const std::string &text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(SceneFile, AcceptsMappingWithNestedKeysAndLists) {
  const auto  path = WriteTemp("ok.yaml", "physics: dem\ndem:\n  radius: 1e-3\ngravity: [0, 0, -9.81]\n");
  std::string msg;
  EXPECT_TRUE(vofdem::CheckSceneFile(path, vofdem::SceneFormat::Yaml, &msg)) << msg;
}

TEST(SceneFile, MalformedYamlNamesFileAndLine) {
  const auto  path = WriteTemp("bad.yaml", "physics: dem\ndem:\n  radius: 1e-3\n   density: [2500\n");
  std::string msg;
  EXPECT_FALSE(vofdem::CheckSceneFile(path, vofdem::SceneFormat::Yaml, &msg));
  EXPECT_NE(msg.find(path + ":4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("malformed YAML"), std::string::npos) << msg;
}

TEST(SceneFile, ListAtTopLevelIsRejected) {
  const auto  path = WriteTemp("list.yaml", "- physics\n- dem\n");
  std::string msg;
  EXPECT_FALSE(vofdem::CheckSceneFile(path, vofdem::SceneFormat::Yaml, &msg));
  EXPECT_NE(msg.find("mapping"), std::string::npos) << msg;
}

TEST(SceneFile, MissingFileIsNamed) {
  std::string msg;
  EXPECT_FALSE(vofdem::CheckSceneFile("/nonexistent/scene.yaml", vofdem::SceneFormat::Plain, &msg));
  EXPECT_EQ(msg.rfind("/nonexistent/scene.yaml:", 0), 0u) << msg;
}
