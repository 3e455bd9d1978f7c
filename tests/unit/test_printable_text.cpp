// Text from plugins and data files: valid UTF-8 kept, invalid bytes replaced, controls shown.
#include "support/text/printable_text.hpp"

#include <doctest/doctest.h>

using sphkern::printable_text;

TEST_CASE("printable text: UTF-8 kept, invalid sequences replaced, control characters escaped")
{
    CHECK(printable_text("Müller ε_ρ 𝜋") == "Müller ε_ρ 𝜋");
    CHECK(printable_text("a\x1b[31mb") == "a\\x1b[31mb");
    CHECK(printable_text("tab\tnewline\n") == "tab\\x09newline\\x0a");
    CHECK(printable_text("del\x7f") == "del\\x7f");
    CHECK(printable_text("c1 \xc2\x9b") == "c1 \\x9b"); // U+009B, the C1 control sequence introducer
    CHECK(printable_text("bad \xff\xfe") == "bad \xef\xbf\xbd\xef\xbf\xbd"); // bytes that start nothing
    CHECK(printable_text("overlong \xc0\xaf") == "overlong \xef\xbf\xbd\xef\xbf\xbd");
    CHECK(printable_text("surrogate \xed\xa0\x80") == "surrogate \xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd");
    CHECK(printable_text("cut \xe2\x82") == "cut \xef\xbf\xbd\xef\xbf\xbd");
    CHECK(printable_text("") == "");
}
