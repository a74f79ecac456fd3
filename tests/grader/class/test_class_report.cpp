// The class report (grader/src/class/class_report.cpp) on made-up student records: no compiler, no
// runner. What it counts, which student it takes as the example, that the same records in
// another order give the same bytes, that a student's text cannot inject HTML or Markdown, and
// that the lecture's view names no student and shows no hidden test.
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "class/class_report.hpp"
#include "reports/text_safety.hpp"

namespace g = jelly::grade;
using g::Json;

namespace {

const std::string kTitle = "The jelly cube";
// The hidden case's inputs, as a real hidden case has them; its failure message quotes them.
const Json kHiddenParams = {{"x_a", {0.893, 0.1174, 2.25}}, {"ks", 713.5}, {"rest", 0.9376}};
const std::string kHiddenMessage =
    "spring_force — on x_a=(0.893, 0.1174, 2.25) ks=713.5 rest=0.9376: expected 41.6602, got 3.3";

g::CaseBook book() {
  g::CaseBook b;
  b.rubric.autograded_total = 10.0;
  b.rubric.tasks.push_back({"A1.T1", "Structural springs", "springs", "", "springs.cpp", 5, false});
  b.rubric.tasks.push_back({"A1.T4", "Spring force", "forces", "", "forces.cpp", 5, false});
  for (const char* id : {"t1.a", "t1.b", "t4.a", "t4.b"}) {
    g::CaseSpec c;
    c.id = id;
    c.task = id[1] == '1' ? "A1.T1" : "A1.T4";
    c.title = std::string("title of ") + id;
    c.hidden = std::string(id) == "t4.b";
    if (c.hidden) c.params = kHiddenParams;
    b.cases.push_back(c);
  }
  return b;
}

Json a_case(const std::string& id, bool passed, const std::string& message = "",
            const std::string& abnormal = "", bool not_run = false) {
  Json f = Json::array();
  if (!message.empty()) f.push_back(message);
  return {{"id", id},
          {"task", id[1] == '1' ? "A1.T1" : "A1.T4"},
          {"hidden", id == "t4.b"},
          {"status", passed ? "passed" : "failed"},
          {"score", passed ? 2.5 : 0.0},
          {"max_score", 2.5},
          {"abnormal", abnormal},
          {"not_run", not_run},
          {"failures", f}};
}

// A graded record: `cases` of the four (the others passed), the task scores from them.
Json graded(const std::string& id, std::vector<Json> failed, Json failed_files = Json::array(),
            Json missing = Json::array()) {
  Json cases = Json::array();
  double t1 = 0, t4 = 0;
  for (const char* cid : {"t1.a", "t1.b", "t4.a", "t4.b"}) {
    Json c = a_case(cid, true);
    for (const Json& f : failed)
      if (f["id"] == cid) c = f;
    (cid[1] == '1' ? t1 : t4) += c["score"].get<double>();
    cases.push_back(c);
  }
  return {{"format", "jelly-grade student record 1"},
          {"assignment", "a1"},
          {"id", id},
          {"name", "Name of " + id},
          {"email", id + "@example.edu"},
          {"status", "graded"},
          {"error", ""},
          {"score", t1 + t4},
          {"max_score", 10.0},
          {"compiled", failed_files.empty()},
          {"missing_files", missing},
          {"failed_files", failed_files},
          {"tasks",
           {{{"id", "A1.T1"}, {"score", t1}, {"max_score", 5.0}, {"bonus", false}},
            {{"id", "A1.T4"}, {"score", t4}, {"max_score", 5.0}, {"bonus", false}}}},
          {"cases", cases}};
}

const std::string kHostile = "<script>alert(1)</script> | **bold** [x](http://e.vil)";

std::vector<Json> the_class() {
  std::vector<Json> r;
  r.push_back(graded("alice", {}));
  r.push_back(graded("bob", {a_case("t4.a", false, "expected 1, got 2")}));
  r.push_back(graded("carol", {a_case("t4.a", false, "expected 1, got 3"),
                               a_case("t4.b", false, kHiddenMessage)}));
  r.push_back(graded("dave",
                     {a_case("t1.a", false, "forces.cpp did not compile", "", true),
                      a_case("t1.b", false, "forces.cpp did not compile", "", true)},
                     Json::array({{{"file", "springs.cpp"},
                                   {"what", "did not compile"},
                                   {"message", "In file springs.cpp:\nsprings.cpp:3:1: error: " +
                                                   kHostile + "\n  3 | x\n"}}})));
  r.push_back(graded("eve", {a_case("t4.a", false, "took longer than 2 s", "timed out"),
                             a_case("t4.b", false, "took longer than 2 s", "timed out")}));
  r.push_back({{"format", "jelly-grade student record 1"},
               {"assignment", "a1"},
               {"id", "frank"},
               {"name", "Frank Notgraded"},
               {"email", "frank@example.edu"},
               {"status", "not graded"},
               {"error", "no task file found " + kHostile}});
  r.push_back(graded("gina", {a_case("t4.a", false, "expected 1, got 0")}, Json::array(),
                     Json::array({"forces.cpp"})));
  r.push_back(graded("mallory" + kHostile, {a_case("t1.b", false, kHostile)}));
  return r;
}

}  // namespace

TEST(ClassReport, CountsGroupsAndExamples) {
  const Json s = g::class_summary(the_class(), book(), kTitle);
  EXPECT_EQ(s["students"], 8);
  EXPECT_EQ(s["graded"], 7);
  EXPECT_EQ(s["not_graded"], 1);
  // Scores out of 10: alice 10, bob 7.5, carol 5, dave 5, eve 5, gina 7.5, mallory 7.5.
  EXPECT_EQ(s["score"]["full_marks"], 1);
  EXPECT_DOUBLE_EQ(s["score"]["median"].get<double>(), 7.5);
  EXPECT_DOUBLE_EQ(s["score"]["mean"].get<double>(), 6.79) << "47.5 / 7, two decimals";
  EXPECT_DOUBLE_EQ(s["score"]["full_marks_share"].get<double>(), 0.143);
  EXPECT_EQ(s["score"]["histogram"][10]["count"], 1) << "full marks";
  EXPECT_EQ(s["score"]["histogram"][7]["count"], 3) << "75%";
  EXPECT_EQ(s["score"]["histogram"][5]["count"], 3) << "50%";
  EXPECT_EQ(s["score"]["histogram"][7]["label"], "70–79%");
  EXPECT_EQ(s["tasks"][0]["scores"]["full_marks"], 5) << "A1.T1: all but dave and mallory";

  const Json& t4 = s["tasks"][1];
  EXPECT_EQ(t4["id"], "A1.T4");
  ASSERT_EQ(t4["failed_cases"].size(), 2u) << t4.dump(1);
  // bob, carol and gina failed t4.a (eve timed out: listed apart); bob first by id.
  EXPECT_EQ(t4["failed_cases"][0]["case"], "t4.a");
  EXPECT_EQ(t4["failed_cases"][0]["students"], 3);
  EXPECT_EQ(t4["failed_cases"][0]["example"]["student"], "bob");
  EXPECT_EQ(t4["failed_cases"][0]["example"]["message"], "expected 1, got 2");
  EXPECT_EQ(t4["failed_cases"][1]["case"], "t4.b");
  EXPECT_EQ(t4["failed_cases"][1]["hidden"], true);
  EXPECT_EQ(t4["failed_cases"][1]["students"], 1);
  // dave's not-run cases are a compile failure, not failed checks.
  const Json& t1 = s["tasks"][0];
  ASSERT_EQ(t1["failed_cases"].size(), 1u) << t1.dump(1);
  EXPECT_EQ(t1["failed_cases"][0]["example"]["student"].get<std::string>().rfind("mallory", 0), 0u);

  ASSERT_EQ(s["did_not_compile"].size(), 1u);
  EXPECT_EQ(s["did_not_compile"][0]["student"], "dave");
  EXPECT_EQ(s["did_not_compile"][0]["file"], "springs.cpp");
  EXPECT_EQ(s["did_not_compile"][0]["message"], "springs.cpp:3:1: error: " + kHostile)
      << "the first error line of the compiler's message";
  ASSERT_EQ(s["timed_out_or_crashed"].size(), 1u);
  EXPECT_EQ(s["timed_out_or_crashed"][0]["student"], "eve");
  EXPECT_EQ(s["timed_out_or_crashed"][0]["abnormal"], "timed out");
  EXPECT_EQ(s["timed_out_or_crashed"][0]["cases"], 2);
  EXPECT_EQ(s["timed_out_or_crashed"][0]["first_case"], "t4.a");
  ASSERT_EQ(s["could_not_grade"].size(), 1u);
  EXPECT_EQ(s["could_not_grade"][0]["student"], "frank");
  ASSERT_EQ(s["missing_files"]["students"].size(), 1u);
  EXPECT_EQ(s["missing_files"]["students"][0]["student"], "gina");
  EXPECT_EQ(s["missing_files"]["by_file"][0]["file"], "forces.cpp");
}

TEST(ClassReport, TheSameRecordsInAnotherOrderGiveTheSameBytes) {
  std::vector<Json> r = the_class();
  const g::CaseBook b = book();
  const Json s = g::class_summary(r, b, kTitle);
  std::reverse(r.begin(), r.end());
  std::rotate(r.begin(), r.begin() + 3, r.end());
  const Json t = g::class_summary(r, b, kTitle);
  EXPECT_EQ(s.dump(), t.dump());
  for (const g::ClassView v : {g::ClassView::Lecture, g::ClassView::Instructor}) {
    EXPECT_EQ(g::class_markdown(s, v), g::class_markdown(t, v));
    EXPECT_EQ(g::class_html(s, v), g::class_html(t, v));
  }
}

TEST(ClassReport, StudentTextIsEscapedInHtmlAndMarkdown) {
  const Json s = g::class_summary(the_class(), book(), kTitle);
  const std::string html = g::class_html(s, g::ClassView::Instructor);
  EXPECT_EQ(html.find("<script"), std::string::npos) << html;
  EXPECT_EQ(html.find("<a "), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  for (const char* section :
       {"<h2>Scores</h2>", "<h2>Tasks</h2>", "<h2>What failed, task by task",
        "<h2>Did not compile</h2>", "<h2>Timed out or crashed</h2>", "<h2>Could not be graded</h2>",
        "<h2>Missing task files</h2>", "<svg", "Instructor-only"})
    EXPECT_NE(html.find(section), std::string::npos) << section;

  const std::string md = g::class_markdown(s, g::ClassView::Instructor);
  EXPECT_EQ(md.find("<script"), std::string::npos) << md;
  EXPECT_NE(md.find("\\[x\\](http://e.vil)"), std::string::npos) << "a student's link stays text";
  EXPECT_EQ(md.find("**bold**"), std::string::npos) << "a student's emphasis stays text";
  for (const char* section :
       {"# What the class got wrong: The jelly cube", "## Scores", "## Tasks",
        "## What failed, task by task", "### A1.T4 Spring force", "## Did not compile",
        "## Timed out or crashed", "## Could not be graded", "## Missing task files",
        "**Missing task files: 1 student** (forces.cpp 1)"})
    EXPECT_NE(md.find(section), std::string::npos) << section << "\n" << md;
  // Every table row of the failed tests has its three cells: a student's | is escaped.
  const auto row = md.find("| t1.b |");
  ASSERT_NE(row, std::string::npos) << md;
  const std::string line = md.substr(row, md.find('\n', row) - row);
  std::size_t bars = 0;
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++bars;
  EXPECT_EQ(bars, 4u) << line;
}

namespace {

// Every number in `j` (the hidden case's parameters), as JSON and as a message shows it.
void numbers_of(const Json& j, std::vector<std::string>& out) {
  if (j.is_number()) {
    out.push_back(j.dump());
    return;
  }
  if (j.is_structured())
    for (const Json& e : j) numbers_of(e, out);
}

// Whether `word` stands in `text` as a word of its own (an id "eve" is not the "eve" of "every").
bool has_word(const std::string& text, const std::string& word) {
  const auto alnum = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool before = at > 0 && alnum(text[at - 1]) && alnum(word.front());
    const bool after =
        at + word.size() < text.size() && alnum(text[at + word.size()]) && alnum(word.back());
    if (!before && !after) return true;
  }
  return false;
}

}  // namespace

TEST(ClassReport, TheLectureViewNamesNoStudentAndShowsNoHiddenTest) {
  const std::vector<Json> records = the_class();
  const g::CaseBook b = book();
  const Json s = g::class_summary(records, b, kTitle);
  const std::string html = g::class_html(s, g::ClassView::Lecture);
  const std::string md = g::class_markdown(s, g::ClassView::Lecture);
  std::vector<std::string> hidden;  // the hidden case's id, title, inputs and failure
  for (const g::CaseSpec& c : b.cases)
    if (c.hidden) {
      hidden.push_back(c.id);
      hidden.push_back(c.title);
      numbers_of(c.params, hidden);
    }
  hidden.push_back("41.6602");  // its expected value
  ASSERT_GE(hidden.size(), 6u);
  const std::string instructor = g::class_html(s, g::ClassView::Instructor);
  EXPECT_NE(instructor.find("713.5"), std::string::npos) << "the instructor's view shows it";
  for (const std::string& text : {html, md}) {
    for (const Json& r : records)
      for (const char* key : {"id", "name", "email"}) {
        const std::string v = r.value(key, "");
        ASSERT_FALSE(v.empty()) << key;
        // The escaped forms too: an id with HTML in it is shown escaped.
        for (const std::string& form : {v, v.substr(0, v.find('<')), g::html_escape(v)})
          EXPECT_FALSE(has_word(text, form)) << key << " " << form << "\n" << text;
      }
    for (const std::string& v : hidden) EXPECT_EQ(text.find(v), std::string::npos) << v;
    EXPECT_EQ(text.find("hidden failure"), std::string::npos);
  }
  // What it shows instead: counts, shares and the tests' titles.
  EXPECT_NE(html.find("What the class got wrong: The jelly cube"), std::string::npos);
  EXPECT_NE(md.find("**43% of the class (3 students)**: failed the test “title of t4.a”"),
            std::string::npos)
      << "bob, carol and gina of 7 graded\n"
      << md;
  EXPECT_NE(md.find("**14% of the class (1 student)**: failed a hidden test of this task"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("- did not compile: 1 student (14%)"), std::string::npos) << md;
  EXPECT_NE(md.find("- timed out: 1 student (14%)"), std::string::npos) << md;
  EXPECT_NE(md.find("- missing task files: 1 student (14%)"), std::string::npos) << md;
  EXPECT_NE(md.find("- could not be graded: 1 student (14%)"), std::string::npos) << md;
  for (const char* instructor_only :
       {"## Did not compile\n", "## Timed out or crashed", "## Could not be graded"})
    EXPECT_EQ(md.find(instructor_only), std::string::npos) << instructor_only;
  EXPECT_NE(html.find("class-instructor.html"), std::string::npos) << "where the rest is";
}

TEST(ClassReport, KnownMistakesAreCountedOncePerStudentInTheHintsWords) {
  std::vector<Json> r;
  const std::string rk4 = "RK4 with equal weights (h/4 each)";
  Json hinted = a_case("t4.a", false, "expected 1, got 2");
  hinted["hints"] = Json::array({rk4});
  Json hinted_too = a_case("t1.a", false, "expected 1, got 2");
  hinted_too["hints"] = Json::array({rk4});
  // ann's mistake shows in two tests of one task: one student.
  Json twice = a_case("t4.a", false, "expected 1, got 2");
  twice["hints"] = Json::array({rk4});
  r.push_back(graded("ann", {twice}));
  r.push_back(graded("ben", {hinted}));
  r.push_back(graded("cid", {a_case("t4.a", false, "expected 1, got 9")}));
  r.push_back(graded("dot", {}));
  r.push_back(graded("eli", {hinted_too}));
  const Json s = g::class_summary(r, book(), kTitle);
  const Json& t4 = s["tasks"][1];
  ASSERT_EQ(t4["known_mistakes"].size(), 1u) << t4.dump(1);
  EXPECT_EQ(t4["known_mistakes"][0]["mistake"], rk4);
  EXPECT_EQ(t4["known_mistakes"][0]["students"], 2);
  EXPECT_DOUBLE_EQ(t4["known_mistakes"][0]["share"].get<double>(), 0.4);
  EXPECT_EQ(s["tasks"][0]["known_mistakes"][0]["students"], 1) << "eli's, in A1.T1";
  const std::string md = g::class_markdown(s, g::ClassView::Lecture);
  EXPECT_NE(md.find("- **40% of the class (2 students)**: RK4 with equal weights (h/4 each)"),
            std::string::npos)
      << md;
  EXPECT_NE(g::class_html(s, g::ClassView::Lecture).find(rk4), std::string::npos);
}

TEST(ClassReport, ACompileErrorIsCountedOnceNotAmongTheCourseScenesFailures) {
  g::CaseBook b = book();
  b.rubric.tasks.push_back(
      {"A1.COURSE", "Course scene (all your code)", "integration", "", "", 0, false});
  g::CaseSpec course;
  course.id = "course";
  course.task = "A1.COURSE";
  course.title = "the course scene";
  b.cases.push_back(course);
  auto with_course = [](Json rec, bool passed) {
    Json c = a_case("course", passed, passed ? "" : "the stability detector fired");
    c["task"] = "A1.COURSE";
    c["max_score"] = 0.0;
    rec["cases"].push_back(c);
    rec["tasks"].push_back(
        {{"id", "A1.COURSE"}, {"score", 0.0}, {"max_score", 0.0}, {"bonus", false}});
    return rec;
  };
  const Json broken =
      Json::array({{{"file", "forces.cpp"}, {"what", "did not compile"}, {"message", "error: x"}}});
  std::vector<Json> r;
  r.push_back(with_course(graded("amy", {}), true));
  // bo's forces.cpp did not compile: its tests are not run, the course scene ran with the stub.
  r.push_back(with_course(graded("bo",
                                 {a_case("t4.a", false, "not run", "", true),
                                  a_case("t4.b", false, "not run", "", true)},
                                 broken),
                          false));
  r.push_back(with_course(graded("cy", {}), false));
  const Json s = g::class_summary(r, b, kTitle);
  const Json& course_task = s["tasks"][2];
  ASSERT_EQ(course_task["id"], "A1.COURSE");
  ASSERT_EQ(course_task["failed_cases"].size(), 1u) << course_task.dump(1);
  EXPECT_EQ(course_task["failed_cases"][0]["students"], 1) << "cy only";
  EXPECT_EQ(course_task["failed_cases"][0]["example"]["student"], "cy");
  ASSERT_EQ(s["failure_kinds"].size(), 1u) << s["failure_kinds"].dump(1);
  EXPECT_EQ(s["failure_kinds"][0]["kind"], "did not compile");
  EXPECT_EQ(s["failure_kinds"][0]["students"], 1);
  // The tasks nobody failed: one line, not a heading each.
  const std::string md = g::class_markdown(s, g::ClassView::Instructor);
  EXPECT_NE(md.find("**No test failed:** A1.T1 Structural springs, A1.T4 Spring force\n"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("### A1.T1"), std::string::npos) << md;
  EXPECT_EQ(md.find("No test failed.\n"), std::string::npos) << md;
  EXPECT_NE(g::class_markdown(s, g::ClassView::Lecture)
                .find("**No test failed:** A1.T1 Structural springs, A1.T4 Spring force\n"),
            std::string::npos);
}
