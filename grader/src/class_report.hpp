// "What the class got wrong": the class report of a batch (class.json, class.md, class.html), made
// from the students' records alone (class_record.hpp) so that a batch, a resumed batch and the
// merge of shards write the same bytes. For the instructor: it names hidden cases.
#pragma once

#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

/// The class report as data (class.json): the score distribution overall and per task, each
/// task's failed cases grouped (most frequent first, with one example student each), and the
/// submissions that did not compile, timed out or crashed, could not be graded or missed files.
/// No times, dates or paths; the same records (in any order) give the same bytes.
Json class_summary(const std::vector<Json>& records, const CaseBook& book);

/// class.md: the summary as Markdown (every student-controlled text escaped).
std::string class_markdown(const Json& summary);

/// class.html: the summary as one self-contained page for a projector (no scripts, no external
/// files; every student-controlled text escaped).
std::string class_html(const Json& summary);

}  // namespace jelly::grade
