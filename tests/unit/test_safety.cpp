// The safety rules of the support layer: JSON duplicates and pointers, the parallel
// executor's error handling, output folders that never replace what sphkern did not write.
#include "kernels/plugin_host/plugin_call_guard.hpp"
#include "support/error.hpp"
#include "support/io/json_input.hpp"
#include "support/io/output_folder.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/work_budget.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace sphkern;
namespace fs = std::filesystem;

namespace {

std::string error_of(const std::function<void()>& f)
{
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

fs::path fresh_folder(const std::string& name)
{
    fs::path p = fs::temp_directory_path() / ("sphkern-test-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

} // namespace

TEST_CASE("a duplicate key is refused with the JSON Pointer of its object, through arrays and escapes")
{
    CHECK(error_of([] { parse_json_text(R"({"a": [{"b": 1}, {"b": 1, "b": 2}]})", "f.json"); }) ==
          "f.json: /a/1: duplicate key \"b\" (each key may appear once)");
    CHECK(error_of([] { parse_json_text(R"({"x/y": {"~": [[1], {"k": 0, "k": 0}]}})", "f.json"); }) ==
          "f.json: /x~1y/~0/1: duplicate key \"k\" (each key may appear once)");
    // The same key in different objects is fine.
    CHECK(parse_json_text(R"({"a": {"k": 1}, "b": {"k": 2}, "c": [{"k": 3}, {"k": 4}]})", "f.json")["c"][1]["k"] == 4);
    CHECK(escape_json_pointer("a/b~c") == "a~1b~0c");
}

TEST_CASE("the parallel executor carries a worker's exception and runs every item once")
{
    std::vector<int> seen(1000, 0);
    ParallelFor ok;
    ok.run(seen.size(), 3, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end && ok.keep_going(); ++i) ++seen[i];
    });
    CHECK(std::count(seen.begin(), seen.end(), 1) == 1000);

    ParallelFor failing;
    CHECK_THROWS_WITH_AS(failing.run(100, 4,
                                     [&](int thread, std::size_t, std::size_t) {
                                         if (thread == 2) throw std::runtime_error("worker 2 failed");
                                     }),
                         "worker 2 failed", std::runtime_error);
}

TEST_CASE("the kept threads serve passes one after another, nested passes and two callers at once")
{
    // Many short passes on kept threads: each item once per pass, on the thread counts asked.
    std::vector<int> seen(64, 0);
    for (int pass = 0; pass < 2000; ++pass) {
        ParallelFor p;
        p.run(seen.size(), 1 + pass % 5, [&](int, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) ++seen[i];
        });
    }
    CHECK(std::count(seen.begin(), seen.end(), 2000) == 64);

    // A pass inside a pass finds the kept threads in use and starts its own.
    std::vector<std::atomic<int>> inner(4 * 8);
    ParallelFor outer;
    outer.run(4, 4, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t o = begin; o < end; ++o) {
            ParallelFor nested;
            nested.run(8, 3, [&](int, std::size_t b, std::size_t e) {
                for (std::size_t i = b; i < e; ++i) ++inner[o * 8 + i];
            });
        }
    });
    CHECK(std::all_of(inner.begin(), inner.end(), [](const auto& v) { return v == 1; }));

    // Two callers at once (a library host's threads): both complete, every item once.
    std::vector<std::atomic<int>> shared(2 * 5000);
    auto caller = [&](std::size_t half) {
        for (int pass = 0; pass < 200; ++pass) {
            ParallelFor p;
            p.run(5000, 3, [&](int, std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) ++shared[half * 5000 + i];
            });
        }
    };
    std::thread other(caller, 1);
    caller(0);
    other.join();
    CHECK(std::all_of(shared.begin(), shared.end(), [](const auto& v) { return v == 200; }));

    // A forked child (an isolated plugin call) has none of the parent's kept threads: its passes still run.
    const pid_t child = fork();
    if (child == 0) {
        std::vector<int> mine(100, 0);
        ParallelFor p;
        p.run(mine.size(), 4, [&](int, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) ++mine[i];
        });
        _exit(std::count(mine.begin(), mine.end(), 1) == 100 ? 0 : 1);
    }
    int status = -1;
    REQUIRE(waitpid(child, &status, 0) == child);
    CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
}

TEST_CASE("an output folder is committed without replacing anything, and --force replaces only its own kind")
{
    fs::path base = fresh_folder("output");
    fs::path target = base / "a" / "b" / "results";
    {
        OutputFolder out(target, false);
        out.write("x.txt", "1\n");
        // Someone creates the target meanwhile: it is not replaced.
        fs::create_directories(target);
        std::ofstream(target / "mine.txt") << "user data\n";
        CHECK(error_of([&] { out.commit(); }).find("already exists (it appeared while this run worked)") !=
              std::string::npos);
    }
    CHECK(fs::exists(target / "mine.txt"));
    CHECK(error_of([&] { OutputFolder out(target, true); }).find("is not a results folder sphkern wrote") !=
          std::string::npos);
    fs::remove_all(target);
    {
        OutputFolder out(target, false);
        out.write("x.txt", "1\n");
        out.commit();
    }
    CHECK(written_by_sphkern(target));
    {
        OutputFolder out(target, true);
        out.write("y.txt", "2\n");
        out.commit();
    }
    CHECK(fs::exists(target / "y.txt"));
    CHECK(!fs::exists(target / "x.txt"));
    // Nothing but the results folder is left: no staging folder, no old copy.
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(target.parent_path())) entries += e.path() != target;
    CHECK(entries == 0);

    // A failed run removes the parents it created, and not those that were there.
    fs::path deep = base / "new1" / "new2" / "results";
    {
        OutputFolder abandoned(deep, false);
    }
    CHECK(!fs::exists(base / "new1"));
    CHECK(fs::exists(base));
    fs::remove_all(base);
}

TEST_CASE("a results path too long for the system fails part of the way and leaves no folder it made")
{
    fs::path base = fresh_folder("long");
    fs::path deep = base;
    while (deep.string().size() < 4200) deep /= "d"; // PATH_MAX is 4096: mkdir fails past it
    const std::string error = error_of([&] { OutputFolder out(deep / "results", false); });
    CHECK(error.find("cannot create") != std::string::npos);
    CHECK(fs::is_empty(base)); // the 2000-odd folders made on the way down are gone
    fs::remove_all(base);
}

TEST_CASE("a plugin call guard marks its thread only, and nests")
{
    const PluginCall w("/p/x.so", "x", "W"), dw("/p/x.so", "x", "dW");
    CHECK(current_plugin_call() == nullptr);
    {
        PluginCallGuard outer(w);
        CHECK(current_plugin_call() == &w);
        CHECK(std::string(w.plugin()) == "/p/x.so: plugin kernel x");
        {
            PluginCallGuard inner(dw);
            CHECK(current_plugin_call() == &dw);
        }
        CHECK(current_plugin_call() == &w);
        const PluginCall* seen = &w;
        std::thread([&] { seen = current_plugin_call(); }).join();
        CHECK(seen == nullptr);
    }
    CHECK(current_plugin_call() == nullptr);
}

TEST_CASE("a budget message writes whole numbers, never 2e+06 against 2e+06")
{
    CHECK(over_budget("n", 2e6, 2e6).empty());
    CHECK(over_budget("n", 2000000.5, 2e6) == "asks for n = 2000001, more than the limit of 2000000; make it smaller");
    CHECK(over_budget("k samples x wave vectors", 2001.0 * 400 * 400 * 400, 1e8) ==
          "asks for k samples x wave vectors = 128064000000, more than the limit of 100000000; make it smaller");
    CHECK(over_budget("n", 3, 2, "a smaller --k or --grid") ==
          "asks for n = 3, more than the limit of 2; make it smaller: a smaller --k or --grid");
}
