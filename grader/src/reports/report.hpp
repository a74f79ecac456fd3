// Every output format of a grading run: terminal summary, Gradescope results.json, PrairieLearn
// results.json, JUnit XML, Markdown and HTML reports (with the centre-of-mass plot).
#pragma once

#include <filesystem>
#include <set>
#include <string>

#include "grading/grade.hpp"
#include "reports/frames.hpp"

namespace jelly::grade {

std::string terminal_summary(const GradeReport& r, bool verbose);
Json gradescope_results(const GradeReport& r, const CaseBook& book);
Json prairielearn_results(const GradeReport& r);
std::string junit_xml(const GradeReport& r);
/// Markdown; the plot is written next to it as com-height.svg, the frames (when given and
/// available) as frames/{yours,reference}/frame_*.png, linked. The layout of every format (also
/// the terminal's and Gradescope's): a summary row per task, then per task its first failed test
/// expanded (messages, hint), its other failed tests and its passed tests folded (<details>).
/// The words of the messages (tolerance 'force', contract §9) link to `terms_link`#anchor (the
/// handout's reading-your-report.md as seen from the report; "": r.terms_page).
std::string markdown_report(const GradeReport& r, const CourseFrames* frames = nullptr,
                            const std::string& terms_link = {});
/// HTML, self-contained: the plot inline, the frames (read from `dir`/frames/...) as base64 PNGs;
/// the same layout and links as markdown_report.
std::string html_report(const GradeReport& r, const CourseFrames* frames = nullptr,
                        const std::filesystem::path& dir = {}, const std::string& terms_link = {});
/// The centre-of-mass height plot (student against reference) of the course scene, or "".
std::string com_plot_svg(const GradeReport& r);

/// Writes the requested formats into `out` (created): results.json (gradescope),
/// prairielearn.json, junit.xml, report.md (+ com-height.svg, frames/), report.html. With
/// `config` and markdown or html requested, renders the course scene's frames first
/// (render_course_frames; never fails the grading: without a renderer the report says why).
void write_reports(const GradeReport& r, const CaseBook& book, const std::filesystem::path& out,
                   const std::set<std::string>& formats, const GradeConfig* config = nullptr);

}  // namespace jelly::grade
