#!/usr/bin/env python3
"""share/scripts/function_lengths.py on small C++ sources whose function lengths are known:
the limit's edge (59, 60, 61 lines), lambdas counted in the function around them, braces in
strings, characters and comments, qualifiers and initialiser lists, and the allowances.
Usage: function_lengths_check.py SOURCE_DIR"""
import pathlib
import subprocess
import sys
import tempfile
import unittest

SCRIPT = (pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".") / "share/scripts/function_lengths.py").resolve()


def function(name, lines, body_line="    x += 1;"):
    """A function `int NAME(int x)` of exactly `lines` lines, signature to closing brace."""
    return "\n".join([f"int {name}(int x)", "{"] + [body_line] * (lines - 4) + ["    return x;", "}"]) + "\n"


class FunctionLengths(unittest.TestCase):
    def run_on(self, sources, *options):
        with tempfile.TemporaryDirectory() as folder:
            for name, text in sources.items():
                (pathlib.Path(folder) / name).write_text(text)
            done = subprocess.run([sys.executable, str(SCRIPT), *options, "."], cwd=folder, capture_output=True,
                                  text=True)
        return done.returncode, done.stdout

    def lengths(self, text):
        code, out = self.run_on({"a.cpp": text}, "--all")
        self.assertEqual(code, 0, out)
        return [line.split(" is ")[0].split(": ", 1)[1] + " " + line.split(" is ")[1].split()[0]
                for line in out.splitlines()]

    def test_the_limit_is_the_longest_allowed(self):
        text = function("f59", 59) + "\n" + function("f60", 60) + "\n" + function("f61", 61)
        code, out = self.run_on({"a.cpp": text})
        self.assertEqual(out, "a.cpp:122: f61 is 61 lines (limit 60)\n")
        self.assertEqual(code, 1)
        self.assertEqual(self.lengths(text), ["f59 59", "f60 60", "f61 61"])

    def test_an_other_limit(self):
        code, out = self.run_on({"a.cpp": function("f", 12)}, "--limit", "11")
        self.assertEqual((code, out), (1, "a.cpp:1: f is 12 lines (limit 11)\n"))
        self.assertEqual(self.run_on({"a.cpp": function("f", 12)}, "--limit", "12"), (0, ""))

    def test_a_lambda_counts_in_its_function(self):
        lam = ["    auto add = [&](int y) {"] + ["        x += y;"] * 10 + ["    };", "    add(1);"]
        text = "\n".join(["int f(int x)", "{"] + lam + ["    x += 1;"] * 45 + ["    return x;", "}"]) + "\n"
        self.assertEqual(self.lengths(text), ["f 62"])
        code, out = self.run_on({"a.cpp": text})
        self.assertEqual((code, out), (1, "a.cpp:1: f is 62 lines (limit 60)\n"))

    def test_lambdas_of_every_shape_and_local_classes_count_inside(self):
        text = ("void f()\n{\n    auto a = [] { return 1; };\n    auto b = [x = 1]() mutable -> int {\n"
                "        return x;\n    };\n    struct Local {\n        int g() const { return 2; }\n    };\n"
                "    run([&](int i) { return i; }, a, b);\n}\n"
                "const auto top = [](int y) {\n    return y;\n};\n"
                "const auto bare = [] {\n    return 0;\n};\n")
        self.assertEqual(self.lengths(text), ["f 11", "top 3", "bare 3"])

    def test_braces_in_strings_characters_and_comments(self):
        text = ('int f(int x)\n{\n    const char* s = "}}} {";  // }\n    char c = \'}\', d = \'\\\'\';\n'
                "    /* } { }\n    } */\n    auto r = R\"delim(}\n)\" }\n)delim\";\n    int n = 1'000'000;\n"
                "#define CLOSE }\n    return x;\n}\nint g() { return 1; }\n")
        self.assertEqual(self.lengths(text), ["f 13", "g 1"])

    def test_control_blocks_and_classes_are_not_functions(self):
        text = ("namespace n {\nstruct S : Base {\n    int v{3};\n    int get() const noexcept { return v; }\n};\n"
                "int h(int x)\n{\n    if (x) {\n        x = 1;\n    } else {\n        x = 2;\n    }\n"
                "    for (int i = 0; i < 2; ++i) {\n    }\n    return x;\n}\n} // namespace n\n"
                "template <class T>\nconcept Sized = requires(T t) {\n    t.size();\n};\n")
        self.assertEqual(self.lengths(text), ["get 1", "h 11"])

    def test_qualifiers_trailing_types_and_initialiser_lists(self):
        text = ("template <class T>\nauto Box<T>::size() const\n    -> std::pair<int, double>\n{\n    return {};\n}\n"
                "Box::Box(int a,\n         int b)\n    : a_(a), b_{b}\n{\n}\n"
                "Box::Box(double a)\n    : a_(a),\n      b_(a)\n{\n}\n"
                "bool Box::operator==(const Box& o) const { return a_ == o.a_; }\n"
                "int Box::operator()(int i) noexcept(true) { return i; }\n")
        self.assertEqual(self.lengths(text),
                         ["Box::size 6", "Box::Box 5", "Box::Box 5", "Box::operator== 1", "Box::operator() 1"])

    def test_allowances_may_not_grow_and_must_go_when_unused(self):
        sources = {"a.cpp": function("long_one", 70) + function("short_one", 10)}
        self.assertEqual(self.run_on(sources, "--allow", "a.cpp:long_one=70"), (0, ""))
        self.assertEqual(self.run_on(sources, "--allow", "a.cpp:long_one"), (0, ""))
        code, out = self.run_on(sources, "--allow", "a.cpp:long_one=69")
        self.assertEqual(code, 1)
        self.assertIn("a.cpp:1: long_one is 70 lines (limit 60; allowed 69", out)
        code, out = self.run_on(sources, "--allow", "a.cpp:long_one=70", "--allow", "a.cpp:short_one=10")
        self.assertEqual(code, 1)
        self.assertEqual(out, "a.cpp:short_one: allowed over 60 lines but no longer is (or is gone): "
                              "remove its allowance\n")
        sources["list.txt"] = "# comment\na.cpp:long_one 70  # why\n"
        self.assertEqual(self.run_on(sources, "--allow-file", "list.txt"), (0, ""))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
