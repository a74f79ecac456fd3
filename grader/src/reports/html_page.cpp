// render_html (html_page.hpp): a page template rendered with kainjow/mustache.
#include "reports/html_page.hpp"

#include <stdexcept>

#include "reports/text_safety.hpp"

namespace jelly::grade {

std::string render_html(std::string_view page, const char* name, HtmlData data) {
  kainjow::mustache::mustache tmpl{std::string(page)};
  if (!tmpl.is_valid())
    throw std::logic_error(std::string("grader/templates/") + name + ": " + tmpl.error_message());
  tmpl.set_custom_escape([](const std::string& s) { return html_escape(s); });
  data.set("stylesheet", std::string(html_stylesheet()));
  std::string out = tmpl.render(data);
  if (!tmpl.is_valid())
    throw std::logic_error(std::string("grader/templates/") + name + ": " + tmpl.error_message());
  return out;
}

}  // namespace jelly::grade
