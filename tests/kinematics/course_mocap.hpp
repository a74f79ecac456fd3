// The course's skeleton and motions (data/mocap/) at the course's scale 0.2, read for A3's tests; a
// file that cannot be read fails the test with the reader's message.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly::testing {

inline const std::filesystem::path kMocap =
    std::filesystem::path(JELLY_SOURCE_DIR) / "data" / "mocap";

inline skeleton::Skeleton course_skeleton() {
  const skeleton::SkeletonResult r = skeleton::read_asf(kMocap / "skeleton.asf", 0.2);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return *r.skeleton;
}

inline skeleton::Motion course_motion(const skeleton::Skeleton& s, const std::string& name) {
  const skeleton::MotionResult r = skeleton::read_amc(kMocap / name, s);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return *r.motion;
}

}  // namespace jelly::testing
