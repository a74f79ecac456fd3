// The replay CSV reader (`jelly render --replay FILE`): what it accepts, and errors naming file,
// line and what was expected.
#include <gtest/gtest.h>

#include <string>

#include "jelly/session/replay.hpp"

namespace jelly::session {
namespace {

TEST(ReplayCsv, ReadsFramesInFileOrderIgnoringExtraColumns) {
  const std::string text =
      "frame,time,particle,x,y,z,vx,vy,vz\n"
      "0,0,0,1,2,3,9,9,9\n"
      "0,0,1,4,5,6,9,9,9\n"
      "\n"
      "7,0.5,0,-1,-2,-3,0,0,0\n"
      "7,0.5,1,-4,-5,-6.5,0,0,0\n";
  const ReplayResult r = parse_replay(text, "t.csv");
  ASSERT_TRUE(r) << r.error;
  ASSERT_EQ(r.replay->frames.size(), 2u);
  EXPECT_EQ(r.replay->particles(), 2);
  EXPECT_EQ(r.replay->frames[1].frame, 7);
  EXPECT_DOUBLE_EQ(r.replay->frames[1].time, 0.5);
  EXPECT_EQ(r.replay->frames[0].x.col(1), Vec3(4, 5, 6));
  EXPECT_EQ(r.replay->frames[1].x.col(1), Vec3(-4, -5, -6.5));
}

TEST(ReplayCsv, ColumnsMayComeInAnyOrder) {
  const ReplayResult r = parse_replay("x,y,z,particle,time,frame\n1,2,3,0,0.25,4\n", "t.csv");
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.replay->frames[0].frame, 4);
  EXPECT_DOUBLE_EQ(r.replay->frames[0].time, 0.25);
  EXPECT_EQ(r.replay->frames[0].x.col(0), Vec3(1, 2, 3));
}

TEST(ReplayCsv, ErrorsNameTheLineAndWhatWasExpected) {
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {"", "t.csv:0: empty file"},
      {"frame,time,particle,x,y\n", "t.csv:1: the header has no column 'z'"},
      {"frame,time,particle,x,y,z\n", "no frames"},
      {"frame,time,particle,x,y,z\n0,0,0,1,2\n", "t.csv:2: expected 6 values"},
      {"frame,time,particle,x,y,z\n0,0,0,1,two,3\n",
       "t.csv:2: column 'y': expected a number, got 'two'"},
      {"frame,time,particle,x,y,z\n0,0,1,1,2,3\n", "t.csv:2: frame 0: expected particle 0, got 1"},
      {"frame,time,particle,x,y,z\n0,0,0,1,2,3\n0,0,1,1,2,3\n1,1,0,1,2,3\n",
       "frame 1 has 1 particles, the first frame has 2"},
      {"frame,time,particle,x,y,z\n0,0,0,1,2,3\n1,1,0,1,2,3\n0,0,0,1,2,3\n",
       "t.csv:4: frame 0 appears again"},
      {"frame,time,particle,x,y,z\n0,0,0,nan,2,3\n", "t.csv:2: particle 0: position is not finite"},
  };
  for (const Case& c : cases) {
    const ReplayResult r = parse_replay(c.text, "t.csv");
    EXPECT_FALSE(r) << c.text;
    EXPECT_NE(r.error.find(c.expected), std::string::npos)
        << "got: " << r.error << "\nexpected: " << c.expected;
  }
  EXPECT_NE(load_replay("/no/such/replay.csv").error.find("/no/such/replay.csv: cannot open"),
            std::string::npos);
}

}  // namespace
}  // namespace jelly::session
