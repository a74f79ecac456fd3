// jelly-grade's HTML pages (report.html, class.html and class-instructor.html, similarity.html):
// each is a Mustache template of grader/templates/ (embedded in the program at build time by
// grader/templates/embed.cmake) rendered with kainjow/mustache, with the one stylesheet
// grader/templates/style.css. Every {{value}} is escaped with html_escape (text_safety.hpp); a
// {{{value}}} is markup the grader made itself (an SVG plot, a line listing it escaped).
#pragma once

#include <kainjow/mustache.hpp>
#include <string>
#include <string_view>

namespace jelly::grade {

using HtmlData = kainjow::mustache::data;
using HtmlList = kainjow::mustache::list;
using HtmlObject = kainjow::mustache::object;

/// The templates (generated from grader/templates/*.mustache and style.css).
std::string_view report_html_template();
std::string_view report_failed_test_template();   ///< a partial of report.html
std::string_view report_course_scene_template();  ///< a partial of report.html
std::string_view class_html_template();
std::string_view similarity_html_template();
std::string_view html_stylesheet();

/// `page` (one of the templates above; `name` names it in errors) rendered with `data`, the
/// stylesheet given as {{{stylesheet}}}. Throws std::logic_error when the template is not valid
/// Mustache (a defect of the program, never of its input).
std::string render_html(std::string_view page, const char* name, HtmlData data);

}  // namespace jelly::grade
