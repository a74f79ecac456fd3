// The skeleton body kind (assignments A3 and A4, kinematics contract §7): its [body] keys, its
// chains ([[chain]], inverse kinematics) and their checks. A skeleton scene is played frame by
// frame through the SkeletonTasks slots, not simulated (skeleton_play.cpp). Registered by
// body.cmake.
#include "jelly/body_kind.hpp"
#include "jelly/skeleton_player.hpp"
#include "jelly/skeleton_scene.hpp"
#include "jelly/world.hpp"
#include "param_rows.hpp"
#include "skeleton_play.hpp"
#include "skeleton_probe.hpp"

namespace jelly::bodies {

namespace {

using namespace params_detail;

constexpr Range kWholeAtLeastMinusOne{true, -1.0, kInf, true, true};
constexpr Range kWindow{true, 2.0, kInf, true, true};
constexpr Range kMaxIterations{true, 0.0, 1e9, true, true};

SkeletonSceneSpec& spec(SceneSpec& s) { return skeleton_scene(s); }
const SkeletonSceneSpec& spec(const SceneSpec& s) { return skeleton_scene(s); }

bool is_warp(const SceneSpec& s, const Ctx&) { return spec(s).mode == SkeletonMode::Warp; }
bool is_blend(const SceneSpec& s, const Ctx&) { return spec(s).mode == SkeletonMode::Blend; }
bool is_ik(const SceneSpec& s, const Ctx&) { return spec(s).mode == SkeletonMode::Ik; }
bool keyframe_written(const SceneSpec& s, const Ctx& c) {
  return is_warp(s, c) && (spec(s).keyframe_in >= 0 || spec(s).keyframe_out >= 0);
}

long long whole(const Value& v) { return std::get<long long>(v); }

// body.frames: M ≥ 2, or 0 for as many frames as the input (contract §5: M ≥ 2).
std::optional<std::string> check_frames_value(const Decl&, const SceneSpec&, const Ctx&,
                                              const Value& v) {
  if (whole(v) == 1)
    return "must be ≥ 2 (a warp's output has M ≥ 2 frames, kinematics contract §5), or 0 for as "
           "many frames as the input, got 1";
  return std::nullopt;
}

// body.keyframe_in, body.keyframe_out: −1 (none) or ≥ 1; the upper bound needs the motion.
std::optional<std::string> check_keyframe_value(const Decl&, const SceneSpec&, const Ctx&,
                                                const Value& v) {
  if (whole(v) == 0)
    return "must be ≥ 1 (a keyframe lies strictly inside the motion: 0 < K < frames − 1, "
           "kinematics contract §5), or −1 for none, got 0";
  return std::nullopt;
}

std::vector<Decl> file_rows() {
  return {
      make(
          "body.asf", Scope::Body, ValueKind::Text, "", Default::None, kAny,
          "The skeleton file (ASF), relative to the scene file",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).asf; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).asf = text(v); }),
      make(
          "body.amc", Scope::Body, ValueKind::Text, "", Default::None, kAny,
          "The motion file (AMC), relative to the scene file; motion A of a blend",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).amc; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).amc = text(v); }),
      make(
          "body.scale", Scope::Body, ValueKind::Real, "", Default::Yes, kPositive,
          "Multiplies the skeleton's lengths and the root's translations (the course's 0.2)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).scale; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).scale = real(v); }),
      make(
          "body.fps", Scope::Body, ValueKind::Real, "1/s", Default::Yes, kPositive,
          "Frames per second of the motion and of what is played (CMU's capture rate)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).fps; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).fps = real(v); }),
      make(
          "body.mode", Scope::Body, ValueKind::Choice, "", Default::Yes, kAny,
          "What the scene plays: the motion as read, a time warp of it, a blend into amc_b, or "
          "inverse kinematics of its chains ([[chain]]) from one of its frames",
          [](const SceneSpec& s, const Ctx&) -> Value {
            return std::string(skeleton_mode_name(spec(s).mode));
          },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            spec(s).mode = *skeleton_mode_from_name(text(v));
          },
          {"playback", "warp", "blend", "ik"}),
  };
}

Decl warp_row(Decl d) { return written_if(std::move(d), is_warp); }
Decl blend_row(Decl d) { return written_if(std::move(d), is_blend); }
Decl ik_row(Decl d) { return citing(written_if(std::move(d), is_ik), "kinematics contract §6"); }

std::vector<Decl> warp_rows() {
  return {
      warp_row(
          checked(make(
                      "body.frames", Scope::Body, ValueKind::Integer, "", Default::Yes,
                      kNonNegative, "A warp's output frames M (≥ 2); 0: as many as the input",
                      [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).frames; },
                      [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).frames = whole(v); }),
                  check_frames_value)),
      written_if(
          checked(
              make(
                  "body.keyframe_in", Scope::Body, ValueKind::Integer, "", Default::Yes,
                  kWholeAtLeastMinusOne,
                  "A warp's keyframe: the input frame (from 0) that lands on keyframe_out; "
                  "-1: none (uniform)",
                  [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).keyframe_in; },
                  [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).keyframe_in = whole(v); }),
              check_keyframe_value),
          keyframe_written),
      written_if(
          checked(make(
                      "body.keyframe_out", Scope::Body, ValueKind::Integer, "", Default::Yes,
                      kWholeAtLeastMinusOne,
                      "A warp's keyframe: the output frame (from 0) where keyframe_in lands; "
                      "-1: none (uniform)",
                      [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).keyframe_out; },
                      [](SceneSpec& s, const Ctx&, const Value& v) {
                        spec(s).keyframe_out = whole(v);
                      }),
                  check_keyframe_value),
          keyframe_written),
  };
}

std::vector<Decl> blend_rows() {
  return {
      blend_row(make(
          "body.amc_b", Scope::Body, ValueKind::Text, "", Default::None, kAny,
          "A blend's motion B (AMC, same skeleton), relative to the scene file",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).amc_b; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).amc_b = text(v); })),
      blend_row(make(
          "body.a", Scope::Body, ValueKind::Integer, "", Default::Yes, kNonNegative,
          "A blend's first blended frame of A (from 0); a + window ≤ A's frames",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).a; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).a = whole(v); })),
      blend_row(make(
          "body.b", Scope::Body, ValueKind::Integer, "", Default::Yes, kNonNegative,
          "A blend's first blended frame of B (from 0); b + window ≤ B's frames",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).b; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).b = whole(v); })),
      blend_row(make(
          "body.window", Scope::Body, ValueKind::Integer, "", Default::Yes, kWindow,
          "A blend's window W: the frames that mix A and B (the course's 20)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).window; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).window = whole(v); })),
  };
}

std::vector<Decl> ik_rows() {
  return {
      ik_row(make(
          "body.frame", Scope::Body, ValueKind::Integer, "", Default::Yes, kNonNegative,
          "Inverse kinematics: the frame of the AMC (from 0) whose posture the first solve "
          "starts from",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).frame; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).frame = whole(v); })),
      ik_row(make(
          "body.step", Scope::Body, ValueKind::Real, "", Default::Yes, kPositive,
          "Inverse kinematics: the step that scales each update x (the course's 0.1)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).step; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).step = real(v); })),
      ik_row(make(
          "body.epsilon", Scope::Body, ValueKind::Real, "", Default::Yes, kPositive,
          "Inverse kinematics: a solve stops when the end is nearer the target than epsilon "
          "(scene units; the course's 1e-3)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).epsilon; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).epsilon = real(v); })),
      ik_row(make(
          "body.max_iterations", Scope::Body, ValueKind::Integer, "", Default::Yes, kMaxIterations,
          "Inverse kinematics: the updates a solve may make (the course's 1000)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).max_iterations; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).max_iterations = whole(v); })),
      ik_row(make(
          "body.limits", Scope::Body, ValueKind::Bool, "", Default::Yes, kAny,
          "Inverse kinematics: clamp each updated channel to its ASF limits (the bonus)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).limits; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).limits = flag(v); })),
      ik_row(make(
          "body.restore", Scope::Body, ValueKind::Bool, "", Default::Yes, kAny,
          "Inverse kinematics: a solve that is not stable puts back the posture it started from "
          "(the bonus)",
          [](const SceneSpec& s, const Ctx&) -> Value { return spec(s).restore; },
          [](SceneSpec& s, const Ctx&, const Value& v) { spec(s).restore = flag(v); })),
  };
}

// ----- [[chain]] -----

IkChainSpec& chain_spec(SceneSpec& s, const Ctx& c) { return ik_chain_specs(s)[c.index]; }
const IkChainSpec& chain_spec(const SceneSpec& s, const Ctx& c) {
  return ik_chain_specs(s)[c.index];
}

std::vector<std::string> chain_names(const SceneSpec& s) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < ik_chain_specs(s).size(); ++i) out.push_back(std::to_string(i));
  return out;
}

std::optional<std::string> schedule_order(const std::vector<ScheduleEntry>& list) {
  for (std::size_t i = 1; i < list.size(); ++i)
    if (!(list[i].time > list[i - 1].time))
      return "times must increase strictly (kinematics contract §11.16): entry " +
             std::to_string(i) + " has time " + format_double(list[i].time) + " s after " +
             format_double(list[i - 1].time) + " s";
  return std::nullopt;
}

std::optional<std::string> check_schedule(const Decl&, const SceneSpec&, const Ctx&,
                                          const Value& v) {
  return schedule_order(std::get<std::vector<ScheduleEntry>>(v));
}

/// Rows of chains whose target is fixed (no schedule).
Decl fixed_target_only(Decl d) {
  return applies_when(
      std::move(d), "chains without a schedule",
      [](const SceneSpec& s, const Ctx& c) {
        return c.index < ik_chain_specs(s).size() && ik_chain_specs(s)[c.index].schedule.empty();
      },
      [](const Bound& b, const SceneSpec&) {
        return "a chain has a target or a schedule of targets, not both, and chain " +
               std::to_string(b.ctx.index) + " has a schedule";
      });
}

Decl target_schedule_row() {
  Decl d = checked(
      make(
          "chain.*.schedule", Scope::Element, ValueKind::Schedule, "s", Default::Yes, kAny,
          "A moving target instead of target: from each time on, linearly towards the next "
          "entry's target (the first before the first time, the last after the last); TOML "
          "[{ time = t, target = [x, y, z] }, ...]",
          [](const SceneSpec& s, const Ctx& c) -> Value { return chain_spec(s, c).schedule; },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            chain_spec(s, c).schedule = std::get<std::vector<ScheduleEntry>>(v);
          }),
      check_schedule);
  d.schedule_value = "target";
  return written_if(
      citing(std::move(d), "kinematics contract §11.16"),
      [](const SceneSpec& s, const Ctx& c) { return !chain_spec(s, c).schedule.empty(); });
}

std::vector<Decl> chain_rows() {
  return with_defaults(
      {
          make(
              "chain.*.start", Scope::Element, ValueKind::Text, "", Default::None, kAny,
              "The chain's start bone, by its ASF name (kinematics contract §6.1)",
              [](const SceneSpec& s, const Ctx& c) -> Value { return chain_spec(s, c).start; },
              [](SceneSpec& s, const Ctx& c, const Value& v) { chain_spec(s, c).start = text(v); }),
          make(
              "chain.*.end", Scope::Element, ValueKind::Text, "", Default::None, kAny,
              "The chain's end bone, by its ASF name: the end of this bone reaches for the target",
              [](const SceneSpec& s, const Ctx& c) -> Value { return chain_spec(s, c).end; },
              [](SceneSpec& s, const Ctx& c, const Value& v) { chain_spec(s, c).end = text(v); }),
          fixed_target_only(written_if(
              make(
                  "chain.*.target", Scope::When, ValueKind::Vector3, "", Default::None, kAny,
                  "The target x* of the end bone's end, in scene units (the skeleton's lengths "
                  "times body.scale); or a schedule",
                  [](const SceneSpec& s, const Ctx& c) -> Value {
                    return chain_spec(s, c).target.value_or(Vec3::Zero());
                  },
                  [](SceneSpec& s, const Ctx& c, const Value& v) {
                    chain_spec(s, c).target = vec(v);
                  }),
              [](const SceneSpec& s, const Ctx& c) {
                return chain_spec(s, c).target.has_value();
              })),
          target_schedule_row(),
      },
      [](SceneSpec& s, const Decl&) { ik_chain_specs(s).emplace_back(); });
}

/// A chain's own cross-checks: its bones named, one target or a schedule.
std::optional<CrossError> check_chain(const IkChainSpec& c, std::size_t i) {
  const std::string key = "chain." + std::to_string(i) + ".";
  if (c.start.empty())
    return CrossError{key + "start", "a chain names its start bone (an ASF bone name), got none"};
  if (c.end.empty())
    return CrossError{key + "end", "a chain names its end bone (an ASF bone name), got none"};
  if (c.target && !c.schedule.empty())
    return CrossError{key + "target",
                      "a chain has a target or a schedule of targets, not both (this one has a "
                      "schedule of " +
                          std::to_string(c.schedule.size()) + " entries)"};
  if (!c.target && c.schedule.empty())
    return CrossError{key + "target",
                      "a chain needs a target [x, y, z] or a schedule of targets, got neither"};
  if (auto msg = schedule_order(c.schedule)) return CrossError{key + "schedule", *msg};
  return std::nullopt;
}

/// An ik scene's chains: at least one, each complete.
std::optional<CrossError> check_chains(const SceneSpec& s) {
  const std::vector<IkChainSpec>& chains = ik_chain_specs(s);
  if (chains.empty())
    return CrossError{"chain",
                      "an ik scene (body.mode = \"ik\") solves at least one chain: [[chain]] with "
                      "start, end and target (kinematics contract §7)"};
  for (std::size_t i = 0; i < chains.size(); ++i)
    if (auto e = check_chain(chains[i], i)) return e;
  return std::nullopt;
}

/// The key of a mode's rows that holds other than its default in a scene of another mode.
std::optional<CrossError> foreign_mode_key(const SceneSpec& s) {
  const SkeletonSceneSpec& k = spec(s);
  const SkeletonSceneSpec defaults;
  const std::string here =
      "; this scene's mode is \"" + std::string(skeleton_mode_name(k.mode)) + "\"";
  if (k.mode != SkeletonMode::Warp) {
    const std::string why = "is a key of a warp (body.mode = \"warp\")" + here;
    if (k.frames != defaults.frames) return CrossError{"body.frames", why};
    if (k.keyframe_in != defaults.keyframe_in) return CrossError{"body.keyframe_in", why};
    if (k.keyframe_out != defaults.keyframe_out) return CrossError{"body.keyframe_out", why};
  }
  if (k.mode != SkeletonMode::Blend) {
    const std::string why = "is a key of a blend (body.mode = \"blend\")" + here;
    if (k.amc_b != defaults.amc_b) return CrossError{"body.amc_b", why};
    if (k.a != defaults.a) return CrossError{"body.a", why};
    if (k.b != defaults.b) return CrossError{"body.b", why};
    if (k.window != defaults.window) return CrossError{"body.window", why};
  }
  if (k.mode != SkeletonMode::Ik) {
    const std::string why = "is a key of inverse kinematics (body.mode = \"ik\")" + here;
    if (k.frame != defaults.frame)
      return CrossError{"body.frame", why + (k.mode == SkeletonMode::Warp
                                                 ? " (did you mean \"frames\", a warp's output "
                                                   "frames?)"
                                                 : "")};
    if (k.step != defaults.step) return CrossError{"body.step", why};
    if (k.epsilon != defaults.epsilon) return CrossError{"body.epsilon", why};
    if (k.max_iterations != defaults.max_iterations) return CrossError{"body.max_iterations", why};
    if (k.limits != defaults.limits) return CrossError{"body.limits", why};
    if (k.restore != defaults.restore) return CrossError{"body.restore", why};
    if (!ik_chain_specs(s).empty())
      return CrossError{"chain",
                        "[[chain]] is a chain of inverse kinematics (body.mode = \"ik\")" + here};
  }
  return std::nullopt;
}

std::string no_table(std::string_view section) {
  return "a skeleton scene has no [" + std::string(section) +
         "]: it plays a motion, it is not simulated";
}

class SkeletonKind final : public BodyKindModule {
 public:
  std::string_view name() const override { return "skeleton"; }
  std::string_view description() const override {
    return "a motion-capture skeleton playing a motion (ASF and AMC files)";
  }
  std::string_view body_phrase() const override { return "a skeleton"; }

  std::vector<Decl> rows() const override {
    std::vector<Decl> rows = file_rows();
    for (std::vector<Decl> part : {warp_rows(), blend_rows(), ik_rows()})
      for (Decl& d : part) rows.push_back(std::move(d));
    return body_section(name(), std::move(rows));
  }

  std::vector<Collection> collections() const override {
    // [[chain]]: an ik scene's chains, named by their position: chain.0.start.
    Collection c = collection("chain", "<i>", "chain", Layout::Indexed, chain_names, chain_rows());
    c.append = [](SceneSpec& s) { ik_chain_specs(s).emplace_back(); };
    c.first_key = "schedule";  // read first: it decides whether target applies
    return {std::move(c)};
  }
  std::string foreign_section(std::string_view section,
                              std::string_view scene_body) const override {
    if (section == "chain")
      return "[[chain]] belongs to skeleton scenes of inverse kinematics (body.type = "
             "\"skeleton\", body.mode = \"ik\"), and this scene's body is " +
             std::string(scene_body);
    return BodyKindModule::foreign_section(section, scene_body);
  }

  std::string foreign_key(const std::string& key, const std::string&,
                          std::string_view scene_body) const override {
    return key +
           " is a key of skeleton scenes (body.type = \"skeleton\"), and this scene's body "
           "is " +
           std::string(scene_body);
  }
  /// A skeleton has no springs, meets nothing and feels no gravity: it plays a motion.
  std::vector<SpringType> spring_types() const override { return {}; }
  std::optional<std::string> refuses_section(std::string_view section) const override {
    if (section == "terrain" || section == "gravity") return no_table(section);
    return std::nullopt;
  }

  /// A skeleton scene's variant is its mode ("playback", "warp", "blend"): A3's manifest claims
  /// those, another assignment of the skeleton claims its own (docs/new-assignment.md).
  std::string scene_variant(const SceneSpec& s) const override {
    return std::string(skeleton_mode_name(spec(s).mode));
  }

  std::optional<CrossError> check(const SceneSpec& s) const override {
    const SkeletonSceneSpec& k = spec(s);
    if (s.gravity) return CrossError{"gravity", no_table("gravity")};  // read before any check
    if (k.asf.empty())
      return CrossError{"body.asf",
                        "a skeleton scene names its ASF file (relative to the scene "
                        "file), got none"};
    if (k.amc.empty())
      return CrossError{"body.amc",
                        "a skeleton scene names its AMC file (relative to the scene "
                        "file), got none"};
    if (auto e = foreign_mode_key(s)) return e;
    if ((k.keyframe_in >= 0) != (k.keyframe_out >= 0)) {
      const bool in = k.keyframe_in >= 0;
      return CrossError{in ? "body.keyframe_out" : "body.keyframe_in",
                        std::string("a keyframe is a pair: give keyframe_in and keyframe_out (") +
                            (in ? "keyframe_in" : "keyframe_out") + " is given), or neither"};
    }
    if (k.mode == SkeletonMode::Blend && k.amc_b.empty())
      return CrossError{"body.amc_b",
                        "a blend names its motion B (an AMC file relative to the "
                        "scene file), got none"};
    if (k.mode == SkeletonMode::Ik) return check_chains(s);
    return std::nullopt;
  }

  std::string_view stability_reason() const override { return "(a skeleton is not simulated)"; }
  std::string_view run_help(std::string_view option) const override {
    return option == "--summary"
               ? "\n                      (a skeleton scene is played, not simulated: per frame i"
                 "\n                      with i / fps ≤ --duration and per bone frame,bone,name,"
                 "\n                      start_x,start_y,start_z,end_x,end_y,end_z, and for a "
                 "warp or a\n                      blend qw,qx,qy,qz; an ik scene's posture after "
                 "each solved\n                      frame, after a # line per solve; "
                 "docs/skeleton-scenes.md)"
               : "";
  }

  // ----- the smoke tests of its task slots (jelly probe, the viewer's hints) -----
  std::vector<std::string_view> probe_slots() const override { return skeleton_probe_slots(); }
  TaskStatus probe_slot(std::string_view slot, std::string id, std::string name,
                        const TaskTable& tasks) const override {
    return probe_skeleton_slot(slot, std::move(id), std::move(name), tasks);
  }

  /// `jelly run` and `jelly check` play and read a skeleton scene without a World (plays_frames);
  /// the viewer and `jelly render` build one: a SkeletonPhysics whose steps play the motion
  /// (jelly/skeleton_player.hpp), on a ground plane under its lowest bone end.
  void build(const SceneSpec& scene, World& world) const override {
    build_skeleton_world(scene, world);
  }

  bool plays_frames() const override { return true; }
  std::string check_frames(const SceneSpec& scene) const override {
    return check_skeleton_scene(scene);
  }
  std::string play(const SceneSpec& scene, const TaskTable& tasks,
                   const FramePlayOptions& options) const override {
    return play_skeleton_scene(scene, tasks, options);
  }
};

}  // namespace

const BodyKindModule& skeleton_kind() {
  static const SkeletonKind kind;
  return kind;
}

}  // namespace jelly::bodies
