# The skeleton (A3 and A4, the kinematics contract): the ASF and AMC readers, postures, motions and
# rotations (§1–§3), and the body kind body.type = "skeleton" (§7), whose scenes are played frame
# by frame through the SkeletonTasks slots rather than simulated (docs/skeleton-scenes.md).
# The accuracy study (docs/skeleton-studies.md) computes the Euler lerp it compares slerp with, the
# warp's time and root translation included: a student release leaves it out (A3's T4).
set(_jelly_skeleton_study "")
if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/skeleton_study.cpp)
  set(_jelly_skeleton_study skeleton_study.cpp)
endif()
# The IK study (docs/ik-studies.md) holds its own IK iteration and variants of A4's tasks: a
# student release leaves it out too.
if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/skeleton_ik_study.cpp)
  list(APPEND _jelly_skeleton_study skeleton_ik_study.cpp)
endif()
jelly_body_kind(skeleton ORDER 40 MODULE skeleton_kind
                SOURCES skeleton.cpp rotation.cpp skeleton_file_text.cpp asf_reader.cpp asf_bone_block.cpp
                        asf_hierarchy.cpp amc_reader.cpp skeleton_kind.cpp skeleton_inputs.cpp skeleton_play.cpp
                        skeleton_ik.cpp skeleton_ik_play.cpp svd_instance.cpp
                        skeleton_player.cpp skeleton_player_ik.cpp skeleton_probe.cpp ${_jelly_skeleton_study})
