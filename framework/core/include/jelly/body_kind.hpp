// A kind of scene body as one module (framework/bodies/<kind>/, docs/architecture.md "Bodies").
//
// General code (the scene reader and writer, the parameter table, build_world, the CLI's summary,
// the studies) never asks which kind a body is: it finds the scene's kind in the registry
// (find_body_kind) and asks it. A kind module implements BodyKindModule and registers itself with
// one line in its folder's body.cmake; CMake writes the list of the kinds a build links
// (BUILD/bodies/linked_body_kinds.cpp), so adding a kind edits no general file.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/scene_spec.hpp"
#include "jelly/spring.hpp"

namespace jelly {

class World;
class Simulator;
class CsvWriter;
struct State;
struct TaskTable;
struct TaskStatus;

namespace params_detail {
struct Decl;
struct Collection;
struct CrossError;
}  // namespace params_detail

/// One value a kind's measure shows in an output of `jelly study effects` (BodyMeasure): which of
/// its kind's BodyStudyValues it is, scaled and formatted how.
struct BodyMeasureColumn {
  std::string_view header;      ///< the CSV's or table's column header, the progress line's label
  int value = 0;                ///< its index in BodyStudyValues::values
  double scale = 1.0;           ///< shown as scale × the value (100: a fraction in %, m in cm)
  const char* format = "%.3g";  ///< the table's or progress line's printf format
  std::string_view unit = "";   ///< the progress line's unit after the number
};

/// Where a kind's measure is listed among the framework's own (impact, bounce, rest, energy).
enum class MeasurePlace {
  /// With the landing: after the bounce in the names and the help, first on the progress line,
  /// and always a column of the plot data before the rest time.
  kLanding,
  /// After the energy in the names and the help, after the bounce on the progress line, and a
  /// column of the plot data after the label when any such measure is on.
  kMotion,
};

/// A measure a body kind takes in `jelly study effects` (BodyKindModule::measures): its name as a
/// manifest's [studies] measures lists it, and how each output shows its values. General code
/// lists the kinds' measures after the bounce in the CSV, the table and the plot, in the order of
/// the linked kinds and of their lists.
struct BodyMeasure {
  std::string_view name;  ///< as a manifest lists it
  MeasurePlace place = MeasurePlace::kMotion;
  std::string_view help;                 ///< its lines of `jelly study effects --help`
  std::vector<BodyMeasureColumn> csv;    ///< its CSV columns (headers without the comma)
  std::vector<BodyMeasureColumn> table;  ///< its Markdown table columns (format: the cell's)
  BodyMeasureColumn progress;            ///< its part of the progress line of a run
  BodyMeasureColumn plot;                ///< its column of the plot data (header: the column's)
  std::string_view plot_label;           ///< its y label in the plot against the swept value
  /// The y label of BodyStudyValues::over_time in the plot over time when the measure is on; ""
  /// when the measure has none.
  std::string_view time_label = "";
};

/// The values of one `jelly study effects` run that its body's kind measures, by the indices its
/// measures' columns give (BodyMeasureColumn::value); NaN where the kind does not take a measure.
struct BodyStudyValues {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> values;  ///< by the kind's own indices
  double over_time = kNone;    ///< what the plot over time follows now (BodyMeasure::time_label)
};

/// Where a study's body is: the centre of mass of the measured particles
/// (BodyKindModule::measured_particles) and its height along `up` (against gravity).
struct StudyLook {
  Vec3 com = Vec3::Zero();
  double height = 0.0;
  Vec3 up = Vec3::UnitY();
};

/// One run's measuring that belongs to a kind (`jelly study effects`): made from the start state
/// by BodyKindModule::study, then shown the state after every step.
class BodyStudy {
 public:
  virtual ~BodyStudy() = default;
  /// The state after a step, and where the body is then.
  virtual void observe(const State& s, const StudyLook& now) = 0;
  /// The values so far (after the start state, before the first observe).
  virtual const BodyStudyValues& values() const = 0;
};

/// What `jelly run` asks of a kind whose scenes play frames (BodyKindModule::plays_frames).
struct FramePlayOptions {
  std::string summary_path;  ///< the `--summary` file; "" for none
  long every = 1;            ///< write every `every`-th frame (frame 0 always)
};

/// One kind of body: what a scene of this kind says (its section of the parameter table), and
/// how it becomes a World.
class BodyKindModule {
 public:
  virtual ~BodyKindModule() = default;

  // ----- its scene section -----
  /// `body.type` as a scene writes it ("rope" for a kind of ropes).
  virtual std::string_view name() const = 0;
  /// What it is, for body.type's description ("a rope of beads").
  virtual std::string_view description() const = 0;
  /// How messages name a scene's body of this kind ("a rope", "particles").
  virtual std::string_view body_phrase() const = 0;
  /// Its rows of the parameter table that are not in a collection, in table order: the [body]
  /// keys, then any table of its own ([collision]). Read by the parameter table once.
  virtual std::vector<params_detail::Decl> rows() const = 0;
  /// Its own collections ([[sphere]]), after the general ones in table order. None by default.
  virtual std::vector<params_detail::Collection> collections() const;
  /// Why a key of this kind's [body] (or other row of rows()) does not apply to a scene whose
  /// body is another kind: `key` the full key, `local` its last part, `scene_body` that scene's
  /// body_phrase().
  virtual std::string foreign_key(const std::string& key, const std::string& local,
                                  std::string_view scene_body) const;
  /// Whether a key of another kind in a scene of this kind is reported with its reason (true)
  /// or as an unknown key (false).
  virtual bool explains_foreign_keys() const { return false; }
  /// Why a top-level table of its own (one of its rows' or collections' tables) is not allowed in
  /// a scene of another kind; `scene_body` is the scene's body name.
  virtual std::string foreign_section(std::string_view section, std::string_view scene_body) const;
  /// Why a general table ([[terrain]]) is not allowed in a scene of this kind; nullopt: allowed.
  virtual std::optional<std::string> refuses_section(std::string_view section) const;
  /// The variant of a scene of this kind: what a manifest's `bodies` entry "kind:variant" names to
  /// claim only such scenes, when two assignments share the kind (jelly/manifest.hpp BodyClaim,
  /// docs/new-assignment.md). "" (the default) for a kind without variants.
  virtual std::string scene_variant(const SceneSpec& scene) const {
    (void)scene;
    return "";
  }

  // ----- its springs -----
  /// The spring types its scenes may have, in the order a scene lists them.
  virtual std::vector<SpringType> spring_types() const;
  /// A spring type's coefficients when a scene (or `--set springs.<type>.enabled=true`) turns it
  /// on without giving them. Unchanged (SpringSettings' defaults) unless the kind says otherwise.
  virtual void spring_defaults(SpringSettings& settings) const { (void)settings; }

  // ----- the TaskTable slots that build its springs (jelly/task_probe.hpp) -----
  /// The slots whose smoke test is this kind's (they take its lattice or grid), in order; none by
  /// default.
  virtual std::vector<std::string_view> probe_slots() const;
  /// Probes `slot` (one of probe_slots()) of `tasks` on a small body of this kind, reporting it
  /// as task `id` named `name`.
  virtual TaskStatus probe_slot(std::string_view slot, std::string id, std::string name,
                                const TaskTable& tasks) const;

  // ----- checks and building -----
  /// The checks of a whole scene of this kind that involve several keys; the first problem.
  virtual std::optional<params_detail::CrossError> check(const SceneSpec& scene) const;
  /// The check that a scene of another kind holds none of this kind's data (its collections'
  /// elements, set in code); the problem or nullopt.
  virtual std::optional<params_detail::CrossError> check_absent(const SceneSpec& scene) const;
  /// Adds the scene's bodies, springs, gravity and whatever else the kind needs to `world`, in
  /// the order its contract fixes.
  virtual void build(const SceneSpec& scene, World& world) const = 0;

  // ----- what a run reports (jelly run, jelly check) -----
  /// The `jelly run --summary` CSV header of a world of this kind. By default the particles'
  /// (kSummaryHeader, jelly/recorder.hpp).
  virtual std::string summary_header(const World& world) const;
  /// Writes the `--summary` row of state `s` at time `t`. By default every particle's.
  virtual void write_summary(CsvWriter& out, const World& world, const State& s, double t) const;
  /// `jelly run`'s report when a run ends (`wall`: its seconds of wall time). By default the
  /// particles' centre of mass, largest speed and energies, and the world's terrains.
  virtual std::string end_report(const SceneSpec& scene, const Simulator& sim, double wall) const;
  /// `jelly check`'s line after the particles and springs: gravity and what else the world holds.
  /// By default the terrains.
  virtual std::string check_report(const SceneSpec& scene, const World& world) const;
  /// The body's line of a rendered frame's caption for a kind that has no view module (a kind with
  /// one gets it from its BodyView), from "\n" to "\n". By default "\n" + body_phrase() + "\n".
  virtual std::string caption_body(const SceneSpec& scene) const;
  /// Why `jelly check` recommends half the stable step ("contact stiffens the body").
  virtual std::string_view stability_reason() const;
  /// What `jelly run --help` adds for this kind to the text of `option` ("--summary": its own
  /// columns; "--threads": when threads pay off); "" (the default) for nothing.
  virtual std::string_view run_help(std::string_view option) const;

  // ----- a kind whose scenes play frames instead of being simulated (a recorded motion) -----
  /// Whether `jelly run` and `jelly check` hand its scenes to play() and check_frames() instead
  /// of building and stepping a World. False by default.
  virtual bool plays_frames() const;
  /// `jelly check` of such a scene: reads what it names and returns the report (counts, notes).
  /// Throws std::runtime_error with the first error (the file and line, or the scene's key).
  virtual std::string check_frames(const SceneSpec& scene) const;
  /// `jelly run` of such a scene through `tasks`: plays it frame by frame, writes the summary
  /// rows and returns the report of what it did. Inputs and slots are checked before any file is
  /// written. Throws std::runtime_error saying what is wrong (a bad input, a slot not filled),
  /// std::system_error when an output file cannot be written.
  virtual std::string play(const SceneSpec& scene, const TaskTable& tasks,
                           const FramePlayOptions& options) const;

  // ----- what the studies measure on it (jelly study effects) -----
  /// How many particles, from the first, a study's centre of mass, speeds and rest are taken over.
  /// By default every particle of the state.
  virtual Eigen::Index measured_particles(const World& world) const;
  /// The measuring of one run from its start state `start` (`look`: where the body is), for the
  /// measures named in `measures` (a manifest's [studies] measures); nullptr (the default) when
  /// the kind measures none of them, so that every value of its measures is NaN.
  virtual std::unique_ptr<BodyStudy> study(const World& world, const State& start,
                                           const StudyLook& look,
                                           const std::vector<std::string>& measures) const;
  /// The measures this kind takes, in the order the outputs list them; none by default.
  virtual const std::vector<BodyMeasure>& measures() const;
  /// What the help adds to "measures needing a contact are nan when nothing touched a terrain"
  /// for this kind; "" by default.
  virtual std::string_view contact_help() const;
};

/// printf into a std::string (the reports above keep the format of the printf calls they were).
#if defined(__GNUC__) || defined(__clang__)
__attribute__((format(printf, 1, 2)))
#endif
std::string
text_printf(const char* format, ...);

/// Every body kind this program links, in the order they are registered (the parameter table's
/// order).
const std::vector<const BodyKindModule*>& body_kinds();
/// The kind called `name`, or nullptr when the program does not link it.
const BodyKindModule* find_body_kind(std::string_view name);
/// The kind of a scene. Throws std::runtime_error naming the scene's file when the program does
/// not link it.
const BodyKindModule& body_kind_of(const SceneSpec& scene);
/// The linked kinds' names, comma-separated in their order, for messages.
std::string body_kind_names();

}  // namespace jelly
