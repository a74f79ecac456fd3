// Unit tests of the grader's small pure modules: what a report may show of a student's bytes
// (text_safety), the class file's fields (csv), which symbols a task file may define (symbols),
// the worker pool every parallel step goes through (parallel), and the tolerance test every
// comparison with the reference makes (tolerance).
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "build/symbols.hpp"
#include "class/csv.hpp"
#include "grading/parallel.hpp"
#include "grading/tolerance.hpp"
#include "reports/text_safety.hpp"

namespace g = jelly::grade;

TEST(GraderText, InvalidUtf8BecomesOneReplacementPerMaximalSubpart) {
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(g::valid_utf8("ok \xC2\xB0 \xF0\x9F\x98\x80"), "ok \xC2\xB0 \xF0\x9F\x98\x80");
  EXPECT_EQ(g::valid_utf8("\xFF\xFE"), fffd + fffd);
  EXPECT_EQ(g::valid_utf8("a\xE6\xB8z"), "a" + fffd + "z");      // a truncated character: one
  EXPECT_EQ(g::valid_utf8("\xC0\xAF"), fffd + fffd);             // overlong
  EXPECT_EQ(g::valid_utf8("\xED\xA0\x80"), fffd + fffd + fffd);  // a UTF-16 surrogate
  EXPECT_EQ(g::valid_utf8("\xF4\x90\x80\x80"), fffd + fffd + fffd + fffd);  // above U+10FFFF
  EXPECT_EQ(g::valid_utf8("\xE2\x86"), fffd);                               // cut at the end
}

TEST(GraderText, CodePointsAreEncodedInOneToFourBytes) {
  std::string s;
  for (const unsigned cp : {0x41u, 0xE9u, 0x20ACu, 0x1F600u, 0x7Fu, 0x80u, 0x7FFu, 0x800u, 0xFFFFu,
                            0x10000u, 0x10FFFFu})
    g::append_utf8(s, cp);
  EXPECT_EQ(s,
            "A\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80\x7F\xC2\x80\xDF\xBF\xE0\xA0\x80"
            "\xEF\xBF\xBF\xF0\x90\x80\x80\xF4\x8F\xBF\xBF");
  EXPECT_EQ(g::valid_utf8(s), s);
}

TEST(GraderText, ControlsBecomeVisibleAndNewlinesStay) {
  EXPECT_EQ(g::safe_text(std::string("a\0b", 3)),
            "a\xE2\x90\x80"
            "b");
  EXPECT_EQ(g::safe_text("\x1b[31mred"), "\xE2\x90\x9B[31mred");
  EXPECT_EQ(g::safe_text("l1\r\nl2\tx\r"), "l1\nl2\tx\xE2\x90\x8D");
  EXPECT_EQ(g::safe_text("\xC2\x9B"
                         "2J"),
            "\xEF\xBF\xBD"
            "2J");  // the one-character CSI
  EXPECT_EQ(g::safe_text("a\xE2\x80\xAE"
                         "b"),
            "a\xEF\xBF\xBD"
            "b");  // right-to-left override
  EXPECT_EQ(g::safe_text("\x7f"), "\xE2\x90\xA1");
}

TEST(GraderText, CutsNeverSplitACharacter) {
  const std::string s = "ab\xE6\xB8\xA9\xF0\x9F\x98\x80";  // a b 温 😀
  EXPECT_EQ(g::cut_utf8(s, 2), "ab");
  EXPECT_EQ(g::cut_utf8(s, 3), "ab");
  EXPECT_EQ(g::cut_utf8(s, 4), "ab");
  EXPECT_EQ(g::cut_utf8(s, 5), "ab\xE6\xB8\xA9");
  EXPECT_EQ(g::cut_utf8(s, 8), "ab\xE6\xB8\xA9");
  EXPECT_EQ(g::cut_utf8(s, 9), s);
  EXPECT_EQ(g::safe_excerpt(s, 4), "ab\xE2\x80\xA6");
}

TEST(GraderText, HtmlAndMarkdownEscapes) {
  EXPECT_EQ(g::html_escape("<script>a&'\"</script>"),
            "&lt;script&gt;a&amp;&#39;&quot;&lt;/script&gt;");
  EXPECT_EQ(g::markdown_inline("**x** [l](u) <b> a|b\nc"),
            "\\*\\*x\\*\\* \\[l\\](u) &lt;b> a\\|b c");
  EXPECT_EQ(g::markdown_inline("- item"), "\\- item");
  EXPECT_EQ(g::markdown_code_block("a ``` b"), "````text\na ``` b\n````\n");
  EXPECT_EQ(g::markdown_code_block("x\n"), "```text\nx\n```\n");
}

// Issue 28: a student's line "Total: 80.00 / 80.00" never starts a line of a plain-text report:
// what the student controls is indented behind a gutter, names stay on one line.
TEST(GraderText, StudentTextIsSetApartInPlainText) {
  EXPECT_EQ(g::set_apart("Total: 80.00 / 80.00\nok\n", "  "),
            "  \xE2\x94\x82 Total: 80.00 / 80.00\n  \xE2\x94\x82 ok\n");
  EXPECT_EQ(g::set_apart("no newline", ""), "\xE2\x94\x82 no newline\n");
  EXPECT_EQ(g::hanging("thrown: x\nTotal: 80.00 / 80.00\n", "    "),
            "thrown: x\n    \xE2\x94\x82 Total: 80.00 / 80.00");
  EXPECT_EQ(g::hanging("one line", "    "), "one line");
  EXPECT_EQ(g::one_line("sub\nTotal: 80"), "sub\xE2\x90\xA4Total: 80");
}

// In Markdown the student's text is a fenced block no line of it can close: the fence is longer
// than its longest run of backticks (a tilde line cannot close a backtick fence).
TEST(GraderText, NoStudentLineClosesItsCodeBlock) {
  const std::string text = "```\n~~~~\n`````` <img src=x onerror=alert(1)>\n";
  const std::string block = g::markdown_code_block(text);
  EXPECT_EQ(block.substr(0, 12), "```````text\n") << block;
  EXPECT_EQ(block.substr(block.size() - 8), "```````\n") << block;
}

// |a − b| ≤ atol + rtol·|b|: the relative part scales with the reference b, not with a; the edge
// passes; NaN never does.
TEST(GraderTolerance, AbsoluteAndRelativePartsAddUpAgainstTheReference) {
  EXPECT_TRUE(g::within_tolerance(1.5, 1.0, 0.5, 0.0));
  EXPECT_FALSE(g::within_tolerance(1.5000001, 1.0, 0.5, 0.0));
  EXPECT_TRUE(g::within_tolerance(110.0, 100.0, 0.0, 0.1));
  EXPECT_FALSE(g::within_tolerance(100.0, 110.0, 0.0, 0.05));
  EXPECT_TRUE(g::within_tolerance(-2.0, -2.0, 0.0, 0.0));
  EXPECT_TRUE(g::within_tolerance(2.5, 2.0, 0.25, 0.125));
  EXPECT_FALSE(g::within_tolerance(std::nan(""), 1.0, 1.0, 1.0));
  EXPECT_FALSE(g::within_tolerance(1.0, std::nan(""), 1.0, 1.0));
  EXPECT_FALSE(g::within_tolerance(INFINITY, INFINITY, 1.0, 1.0));
  EXPECT_EQ(g::allowed_difference(-4.0, 1.0, 0.5), 3.0);
}

TEST(GraderCsv, FieldsAreQuotedAndFormulasMarkedAsText) {
  EXPECT_EQ(g::csv_field("alice"), "alice");
  EXPECT_EQ(g::csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(g::csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(g::csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(g::csv_field(" padded"), "\" padded\"");
  EXPECT_EQ(g::csv_field("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
  EXPECT_EQ(g::csv_field("+1"), "'+1");
  EXPECT_EQ(g::csv_field("-1.5", false), "-1.5");  // a number stays a number
  EXPECT_EQ(g::csv_row({"a", "", "b"}), "a,,b\r\n");
}

TEST(GraderSymbols, NmOutputIsReadPerFileAndArchive) {
  const auto m = g::parse_nm(
      "f.o: _Z3fooi T 0 3\nlib.a[x.o]: bar W 10 2\nlib.a[y.o]: baz D 0 8\n"
      "garbage line\n");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m.at("f.o").at(0).name, "_Z3fooi");
  EXPECT_EQ(m.at("lib.a").size(), 2u);
  EXPECT_TRUE(m.at("lib.a").at(0).weak());
  EXPECT_FALSE(m.at("lib.a").at(1).weak());
}

TEST(GraderSymbols, OnlyOwnTasksHelpersAndHeaderCopiesAreAllowed) {
  g::FrameworkSymbols fw;
  fw.strong = {"_ZN5jelly5grade15install_sandboxEi", "seccomp_load"};
  fw.weak = {"_ZN5jelly4lerpEddd"};
  const std::set<std::string> own = {"_ZN5jelly5tasks12spring_forceEv"};
  const std::map<std::string, std::string> others = {
      {"_ZN5jelly5tasks8rk4_stepEv", "integrators.cpp"}};
  auto why = [&](const std::string& name, char type) {
    return g::refused_symbol("forces.cpp", {name, type}, own, others, fw);
  };
  EXPECT_EQ(why("_ZN5jelly5tasks12spring_forceEv", 'T'), "");
  EXPECT_EQ(why("_ZN5jelly5tasks6helperEd", 'T'), "");  // a non-static helper of its own
  EXPECT_EQ(why("_ZN5jelly4lerpEddd", 'W'), "");        // the framework's inline copy
  EXPECT_EQ(why("_ZNSt6vectorIdSaIdEE17_M_realloc_insertEv", 'W'), "");  // a template instance
  EXPECT_EQ(why("DW.ref.__gxx_personality_v0", 'V'), "");
  EXPECT_NE(why("_ZN5jelly5grade15install_sandboxEi", 'T').find("grader's own code"),
            std::string::npos);
  EXPECT_NE(why("_ZN5jelly5grade15install_sandboxEi", 'W').find("grader's own code"),
            std::string::npos);
  EXPECT_NE(why("_ZN5jelly4lerpEddd", 'T').find("grader's own code"), std::string::npos);
  EXPECT_NE(why("_ZN5jelly5tasks8rk4_stepEv", 'T').find("integrators.cpp"), std::string::npos);
  EXPECT_NE(why("malloc", 'T').find("not a C++ function"), std::string::npos);
  EXPECT_NE(why("seccomp_load", 'T').find("grader's own code"), std::string::npos);
  EXPECT_NE(why("_ZSt9terminatev", 'T').find("standard library"), std::string::npos);
  EXPECT_NE(why("_Znwm", 'T').find("standard library"), std::string::npos);
}

TEST(GraderParallel, EveryIndexRunsOnceOnAtMostTheWorkersAskedFor) {
  for (const std::size_t count : {0u, 1u, 3u, 100u})
    for (const int jobs : {1, 2, 7}) {
      std::vector<std::atomic<int>> calls(count);
      std::atomic<int> running{0}, most{0};
      g::parallel_for(count, jobs, [&](std::size_t i) {
        const int now = ++running;
        for (int seen = most; now > seen && !most.compare_exchange_weak(seen, now);) {
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        ++calls[i];
        --running;
      });
      for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(calls[i].load(), 1) << i << " of " << count;
      EXPECT_LE(most.load(), jobs);
    }
  EXPECT_EQ(g::worker_count(3), 3);
  EXPECT_GE(g::worker_count(0), 1);  // 0: one per core
}

TEST(GraderParallel, AnEscapingExceptionIsRethrownAfterEveryIndexRan) {
  std::vector<std::atomic<int>> calls(50);
  try {
    g::parallel_for(calls.size(), 4, [&](std::size_t i) {
      ++calls[i];
      if (i == 7 || i == 30) throw std::runtime_error("index " + std::to_string(i));
    });
    ADD_FAILURE() << "no exception reached the caller";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "index 7");  // the lowest index that threw, whatever finished first
  }
  for (std::size_t i = 0; i < calls.size(); ++i) EXPECT_EQ(calls[i].load(), 1) << i;
}
