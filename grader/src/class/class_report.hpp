// "What the class got wrong": the class report of a batch, made from the students' records alone
// (class_record.hpp) so that a batch, a resumed batch and the merge of shards write the same
// bytes. class.json holds all of it; class.md and class.html are the view to project in the
// lecture (no student, no hidden test), class-instructor.md and class-instructor.html the
// instructor's (it names students and hidden cases).
#pragma once

#include <string>
#include <vector>

#include "inputs/cases.hpp"

namespace jelly::grade {

/// Which view of the class report: the lecture's (class.md, class.html: to project; it names no
/// student and shows no hidden test, its input or expected values, only counts) or the
/// instructor's (class-instructor.md, class-instructor.html: every student and test named).
enum class ClassView { Lecture, Instructor };

/// The class report as data (class.json, the instructor's): the assignment's title, the score
/// distribution overall and per task, each task's known mistakes (the hints of hints.hpp its
/// students' failed public tests carry, each counted once per student) and failed cases grouped
/// (most frequent first, with one example student each), how many failed a hidden test of each
/// task, the submissions that did not compile, timed out or crashed, could not be graded or missed
/// files, and those counted by kind. A student whose file did not compile is not counted among the
/// failures of a task with no file of its own (a course scene running all of their code): those
/// follow from the compile error, counted once. No times, dates or paths; the same records (in any
/// order) give the same bytes.
Json class_summary(const std::vector<Json>& records, const CaseBook& book,
                   const std::string& title);

/// The summary as Markdown (every student-controlled text escaped).
std::string class_markdown(const Json& summary, ClassView view);

/// The summary as one self-contained page for a projector or a browser (no scripts, no external
/// files; every student-controlled text escaped).
std::string class_html(const Json& summary, ClassView view);

}  // namespace jelly::grade
