// The IK study (kinematics contract §10, docs/ik-studies.md): inverse kinematics' error against
// updates and time for step sizes, epsilons and solvers, and its hard cases, through the task
// table this program links (JELLY_TASKS), as `jelly run` would solve. The study itself is the
// skeleton module's (framework/bodies/skeleton/skeleton_ik_study.cpp); this is its command line.
//
//   ik_study [--asf F] [--amc F] [--frame N] [--scale S] [--start BONE] [--end BONE]
//            [--target X,Y,Z] [--out PREFIX] [--repeats R]
#include <cstdio>
#include <exception>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "jelly/a4/task_table.hpp"
#include "skeleton_ik_study.hpp"

namespace {

constexpr const char* kHelp = R"(usage: ik_study [options]

Solves one inverse-kinematics problem (by default the course's hw3-ik: data/mocap/IK.amc frame 0,
scale 0.2, lowerback -> rfingers, target (-0.0692501, 3.85358, -1.63441)) many ways with the linked
tasks: step sizes 0.01 to 1, epsilons 1e-2 to 1e-6, the minimum-norm solve against damped least
squares, the Jacobian transpose and the exact Euler-angle Jacobian, and the hard cases (a target
out of reach, a straight arm, limits on). Writes PREFIX-runs.csv (one row per solve) and
PREFIX-trace.csv (the error after every update and the processor time to reach it, the median of
--repeats runs).

options:
  --asf FILE, --amc FILE   the skeleton and motion (default data/mocap/skeleton.asf, IK.amc)
  --frame N                the motion's frame to start from (default 0)
  --scale S                the skeleton's scale (default 0.2)
  --start BONE, --end BONE the chain (default lowerback, rfingers)
  --target X,Y,Z           the target (default hw3-ik's)
  --out PREFIX             output files (default study-ik)
  --repeats R              timing runs, 1 to 1000 (default 5)

exit codes: 0 done; 2 bad command line, file or slot; 1 a file could not be written.
)";

int usage_error(const std::string& message) {
  std::fprintf(stderr, "ik_study: %s\n(see ik_study --help)\n", message.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace jelly;
  CLI::App cmd("", "ik_study");
  cmd.set_help_flag("-h,--help");
  cmd.allow_windows_style_options(false);
  std::string asf = JELLY_SOURCE_DIR "/data/mocap/skeleton.asf";
  std::string amc = JELLY_SOURCE_DIR "/data/mocap/IK.amc";
  std::string start = "lowerback", end = "rfingers", prefix = "study-ik";
  int frame = 0, repeats = 5;
  double scale = 0.2;
  std::vector<double> target{-0.0692501, 3.85358, -1.63441};
  cmd.add_option("--asf", asf);
  cmd.add_option("--amc", amc);
  cmd.add_option("--frame", frame);
  cmd.add_option("--scale", scale);
  cmd.add_option("--start", start);
  cmd.add_option("--end", end);
  cmd.add_option("--target", target)->delimiter(',')->expected(3);
  cmd.add_option("--out", prefix);
  cmd.add_option("--repeats", repeats)->check(CLI::Range(1, 1000));
  try {
    cmd.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(kHelp, stdout);
    return 0;
  } catch (const CLI::ParseError& e) {
    return usage_error(e.what());
  }
  try {
    // A4's task table as the build links it (JELLY_TASKS: the students' or the reference's).
    const TaskTable table = a4::task_table();
    const SkeletonTasks& tasks = skeleton_tasks(table);
    const bodies::IkStudyInputs in = bodies::read_ik_study_inputs(
        asf, amc, frame, scale, start, end, Vec3(target[0], target[1], target[2]), tasks);
    std::fputs(bodies::write_ik_study(bodies::study_ik(in, tasks, repeats), prefix).c_str(),
               stdout);
  } catch (const std::system_error& e) {
    std::fprintf(stderr, "ik_study: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    return usage_error(e.what());
  }
  return 0;
}
