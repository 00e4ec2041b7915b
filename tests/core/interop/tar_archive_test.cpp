// ustar archives of export files: GNU tar lists and unpacks them byte for byte.
#include "core/interop/tar_archive.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

TEST(TarArchive, TarUnpacksTheFiles) {
  const std::vector<ExportFile> files = {
      {"hall_agents.yaml", "hunav_loader:\n  ros__parameters: {}\n"},
      {"behavior_trees/hall_agents__agent_1_bt.xml", std::string(700, 'x')},
      {"empty.txt", ""}};
  auto tar = tar_archive(files);
  ASSERT_TRUE(tar) << tar.error().message();
  EXPECT_EQ(tar->size() % 512, 0u);
  if (std::system("tar --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no tar program to unpack with";
  const auto dir = std::filesystem::temp_directory_path() / ("socsim_tar_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(dir / "x.tar", std::ios::binary);
    out << *tar;
  }
  ASSERT_EQ(std::system(("cd '" + dir.string() + "' && tar xf x.tar").c_str()), 0);
  for (const auto& f : files) EXPECT_EQ(testing::read_text((dir / f.path).string()), f.content) << f.path;
  std::filesystem::remove_all(dir);
}

TEST(TarArchive, RefusesPathsOutsideTheArchive) {
  EXPECT_FALSE(tar_archive({{"../etc/passwd", "x"}}));
  EXPECT_FALSE(tar_archive({{"/abs", "x"}}));
  EXPECT_FALSE(tar_archive({{std::string(300, 'a'), "x"}}));
}

}  // namespace
}  // namespace socsim::interop
