// CSV trajectories from a trajectory log: header, one row per agent per frame, numbers that read
// back to the logged floats, state and role names.
#include "core/interop/trajectory_csv.hpp"

#include <charconv>
#include <sstream>

#include <gtest/gtest.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/interop/pedsim_program.hpp"
#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) out.push_back(cell);
  return out;
}

TEST(TrajectoryCsv, RowsReadBackToTheLoggedValues) {
  const scenario::TrajectoryLog log = testing::run_hall(3.0).log;
  const std::string csv = trajectories_csv(log);
  std::stringstream lines(csv);
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));
  EXPECT_EQ(line, "t,id,x,y,vx,vy,state,role,group_id");
  std::size_t rows = 0;
  for (std::size_t f = 0; f < log.frame_count(); ++f) {
    for (const scenario::LoggedAgent& a : log.frame(f)) {
      ASSERT_TRUE(std::getline(lines, line));
      const auto cells = split(line);
      ASSERT_EQ(cells.size(), 9u) << line;
      EXPECT_DOUBLE_EQ(std::stod(cells[0]), log.frame_time(f));
      EXPECT_EQ(std::stoul(cells[1]), a.id);
      float x = 0;
      std::from_chars(cells[2].data(), cells[2].data() + cells[2].size(), x);
      EXPECT_EQ(x, a.x) << line;  // shortest text of a float reads back to the same float
      EXPECT_EQ(cells[6], crowd::activity_name(a.activity));
      EXPECT_EQ(cells[7], log.roles().at(a.role));
      EXPECT_EQ(std::stoi(cells[8]), a.group_id);
      ++rows;
    }
  }
  EXPECT_FALSE(std::getline(lines, line));
  EXPECT_EQ(rows, 31u * 21u);  // frames at 0, 0.1 … 3.0 s, 21 agents (robot included)
  EXPECT_NE(csv.find(",child,"), std::string::npos);
  EXPECT_NE(csv.find(",robot,"), std::string::npos);
}

}  // namespace
}  // namespace socsim::interop
