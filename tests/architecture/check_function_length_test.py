#!/usr/bin/env python3
"""Tests of check_function_length.py's scanner on small C++ sources whose functions and lengths are
counted by hand (the expected values below are read off the sources as written)."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_function_length as check  # noqa: E402


def functions(source):
    return [(f.name, f.line, f.length) for f in check.scan(check.blank(source), "test.cpp")]


def body(lines):
    return "".join(f"    x += {i};\n" for i in range(lines))


class ScannerTest(unittest.TestCase):
    def test_free_and_member_functions_with_their_lines(self):
        source = ("#include <x>\n"                       # 1
                  "namespace tt::ui {\n"                 # 2
                  "\n"                                   # 3
                  "int twice(int x) {\n"                 # 4
                  "    return 2 * x;\n"                  # 5
                  "}\n"                                  # 6
                  "\n"                                   # 7
                  "QString Page::title() const {\n"      # 8
                  "    return tr(\"}{\");\n"             # 9: braces in a string do not count
                  "}\n"                                  # 10
                  "}  // namespace tt::ui\n")
        self.assertEqual(functions(source), [("twice", 4, 3), ("Page::title", 8, 3)])

    def test_constructor_with_brace_initialised_members(self):
        source = ("Wizard::Wizard(int a, QWidget* parent)\n"   # 1
                  "    : Base(parent),\n"                      # 2
                  "      m_ctx{&a, {1, 2}},\n"                 # 3: not the body
                  "      m_list{} {\n"                         # 4: the body opens here
                  "    build();\n"                             # 5
                  "}\n")                                       # 6
        self.assertEqual(functions(source), [("Wizard::Wizard", 1, 6)])

    def test_lambdas_and_local_classes_count_towards_their_function(self):
        source = ("void Tool::connectAll() {\n"
                  "    connect(a, &A::b, this, [this] {\n"
                  "        if (x) { y(); }\n"
                  "    });\n"
                  "    struct Local { int f() { return 1; } };\n"
                  "}\n")
        self.assertEqual(functions(source), [("Tool::connectAll", 1, 6)])

    def test_classes_enums_initialisers_and_comments_are_not_functions(self):
        source = ("namespace {\n"
                  "/* void commented() { } */\n"
                  "// void alsoCommented() {\n"
                  "struct Row { int f() { return 0; } };\n"
                  "enum class Kind : int { A, B };\n"
                  "const std::array<int, 2> kValues = {1, 2};\n"
                  "const QColor kColour{1, 2, 3};\n"
                  "template <class T> T id(T v) {\n"
                  "    return v;\n"
                  "}\n"
                  "}  // namespace\n"
                  "bool operator==(const A& a, const A& b) {\n"
                  "    return a.x == b.x;\n"
                  "}\n"
                  "const auto square = [](double x) {\n"
                  "    return x * x;\n"
                  "};\n")
        self.assertEqual(functions(source), [("id", 8, 3), ("operator==", 12, 3), ("square", 15, 3)])

    def test_raw_strings_digit_separators_and_macros_without_semicolon(self):
        source = ('Q_LOGGING_CATEGORY(lcTest, "tt.test")\n'
                  "int big() {\n"
                  "    const int n = 1'000;\n"
                  "    const char open = '{';\n"
                  '    const char* s = R"x(a "} b c)x";\n'
                  "    return n + open;\n"
                  "}\n"
                  "int next() { return 0; }\n")
        self.assertEqual(functions(source), [("big", 2, 6), ("next", 8, 1)])

    def test_limit_layout_builders_and_excluded_files(self):
        with tempfile.TemporaryDirectory() as root:
            os.makedirs(os.path.join(root, "ui", "run"))
            os.makedirs(os.path.join(root, "ui", "pages"))

            def write(path, text):
                with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                    f.write(text)

            # 60 lines in all (signature + 58 + closing brace) passes; 61 does not.
            write("ui/pages/fits.cpp", "void Page::fits() {\n" + body(58) + "}\n")
            write("ui/pages/builder.cpp", "void Page::buildLayout() {\n" + body(90) + "}\n"
                                          "void Page::makeFormLayout() {\n" + body(90) + "}\n")
            write("ui/run/panel.cpp", "Panel::Panel() {\n" + body(70) + "}\n")
            self.assertEqual(check.main(["--root", root, "ui", "runtime"]), 1)  # ui/run offends
            self.assertEqual(check.main(["--root", root, "--exclude", "ui/run/*", "ui", "runtime"]), 0)
            write("ui/pages/long.cpp", "void Page::tooLong() {\n" + body(59) + "}\n")
            self.assertEqual(check.main(["--root", root, "--exclude", "ui/run/*", "ui", "runtime"]), 1)
            with open(os.path.join(root, "ui/pages/long.cpp"), encoding="utf-8") as f:
                found = check.scan(check.blank(f.read()), "long.cpp")
            self.assertEqual([(f.name, f.length) for f in found], [("Page::tooLong", 61)])


if __name__ == "__main__":
    unittest.main()
