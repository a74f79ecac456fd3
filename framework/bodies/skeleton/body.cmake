# The skeleton (A3 and A4, the kinematics contract §1–§3): the ASF and AMC readers, postures,
# motions and rotations. Shared code for now: the body kind that uses it registers later.
jelly_body_module(SOURCES skeleton.cpp rotation.cpp skeleton_file_text.cpp asf_reader.cpp asf_bone_block.cpp
                          asf_hierarchy.cpp amc_reader.cpp)
