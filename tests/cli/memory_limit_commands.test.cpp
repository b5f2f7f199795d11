#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

using namespace apcs;
using test::run_apcs;
using test::TempFolder;

namespace {

// Sets APCS_MEMORY_LIMIT while it lives and puts back what was there.
class MemoryLimitVariable {
public:
    explicit MemoryLimitVariable(const char* value)
    {
        if (const char* old = std::getenv("APCS_MEMORY_LIMIT"))
            m_old = old;
        ::setenv("APCS_MEMORY_LIMIT", value, 1);
    }
    ~MemoryLimitVariable()
    {
        if (m_old)
            ::setenv("APCS_MEMORY_LIMIT", m_old->c_str(), 1);
        else
            ::unsetenv("APCS_MEMORY_LIMIT");
    }
    MemoryLimitVariable(const MemoryLimitVariable&) = delete;
    MemoryLimitVariable& operator=(const MemoryLimitVariable&) = delete;

private:
    std::optional<std::string> m_old;
};

void write_keys(const TempFolder& folder)
{
    folder.write("key1.dat", "0 0 0\n0 0 10\n0 6 0\n0 6 10\n");
    folder.write("key2.dat", "0 0 10\n0 0 0\n0 5 0\n");
    folder.write("way1.dat", "0 0 0\n3 -4 5\n0 0 10\n");
    folder.write("way4.dat", "0 6 10\n-3 10 5\n0 5 0\n");
}

} // namespace

TEST_CASE("apcs path over the memory limit is refused before sampling, exit 1", "[cli][memory]")
{
    const TempFolder folder;
    folder.write("way.dat", "0 0 0\n1 1 0\n2 0 0\n");
    const MemoryLimitVariable limit("160K");
    // 2001 samples x (24 + 60) + 12 x (48 + 60) + 3 x 320 = 170340 bytes.
    const auto refused = run_apcs({"path", (folder / "way.dat").string(), "--samples", "1000"});
    CHECK(refused.status == 1);
    CHECK(refused.out.empty());
    CHECK(refused.err == "apcs: 3 control points x 1000 samples per segment (--samples) and 12 in-betweens "
                         "(--inbetweens) need 166.3 KiB; the memory limit is 160 KiB (APCS_MEMORY_LIMIT); lower "
                         "--samples or --inbetweens\n");
    // 1601 samples fit: 136740 bytes.
    const auto accepted = run_apcs({"path", (folder / "way.dat").string(), "--samples", "800"});
    CHECK(accepted.status == 0);
    CHECK(accepted.err.empty());
}

TEST_CASE("a 1000-point path with --samples 100000 is refused under the default limit", "[cli][memory]")
{
    const TempFolder folder;
    std::string text;
    for (int i = 0; i < 1000; ++i)
        text += std::to_string(i) + " " + std::to_string(i % 7) + " 0\n";
    folder.write("long.dat", text);
    const auto refused = run_apcs({"path", (folder / "long.dat").string(), "--samples", "100000"});
    CHECK(refused.status == 1);
    CHECK(refused.out.empty());
    CHECK(refused.err == "apcs: 1000 control points x 100000 samples per segment (--samples) and 12 in-betweens "
                         "(--inbetweens) need 7.8 GiB; the memory limit is 4 GiB (APCS_MEMORY_LIMIT); lower "
                         "--samples or --inbetweens\n");
}

TEST_CASE("apcs fit over the memory limit is refused before fitting, exit 1", "[cli][memory]")
{
    const TempFolder folder;
    write_keys(folder);
    const MemoryLimitVariable limit("400K");
    // 1002 x 4 x 84 + 4 x 608 for the printed frames, 2 x (1000 x 48 + 3 x 320) for the paths.
    const auto refused = run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                   (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--inbetweens",
                                   "1000", "--print"});
    CHECK(refused.status == 1);
    CHECK(refused.out.empty());
    CHECK(refused.err == "apcs: 1002 frames of 4 points (--inbetweens 1000) and their paths need 426.8 KiB; the memory "
                         "limit is 400 KiB (APCS_MEMORY_LIMIT); lower --inbetweens or --samples, or use key frames of "
                         "fewer points\n");
}

TEST_CASE("apcs fit writing its in-betweens one at a time counts the keys, not every frame", "[cli][memory]")
{
    const TempFolder folder;
    write_keys(folder);
    const std::vector<std::string> fit{"fit",
                                       (folder / "key1.dat").string(),
                                       (folder / "key2.dat").string(),
                                       (folder / "way1.dat").string(),
                                       (folder / "way4.dat").string(),
                                       "--inbetweens",
                                       "1000",
                                       "--out",
                                       folder.path().string()};
    {
        // 2 x 4 x 24 + 4 x 608 for the keys, 2 x (1000 x 48 + 3 x 320) for the paths: 100544
        // bytes, where all 1002 frames held would need 426.8 KiB.
        const MemoryLimitVariable limit("98K");
        const auto refused = run_apcs(fit);
        CHECK(refused.status == 1);
        CHECK(refused.err == "apcs: the key frames (2 frames of 4 points), the in-betweens made one at a time "
                             "(--inbetweens 1000), and their paths need 98.2 KiB; the memory limit is 98 KiB "
                             "(APCS_MEMORY_LIMIT); lower --inbetweens or --samples, or use key frames of fewer points\n");
        CHECK_FALSE(std::filesystem::exists(folder / "inb001.dat"));
    }
    const MemoryLimitVariable limit("99K");
    const auto written = run_apcs(fit);
    CHECK(written.status == 0);
    CHECK(std::filesystem::exists(folder / "inb1000.dat"));
}

TEST_CASE("apcs inbetween over the memory limit writes no file, exit 1", "[cli][memory]")
{
    const TempFolder folder;
    write_keys(folder);
    const MemoryLimitVariable limit("64K");
    // 1001 x 4 x 24 + 4 x 608 = 98528 bytes.
    const auto refused = run_apcs({"inbetween", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                   "--frames", "1000", "--out", folder.path().string()});
    CHECK(refused.status == 1);
    CHECK(refused.err == "apcs: 1001 frames of 4 points need 96.2 KiB; the memory limit is 64 KiB (APCS_MEMORY_LIMIT); "
                         "lower --frames or --inbetweens, or use key frames of fewer points\n");
    CHECK_FALSE(std::filesystem::exists(folder / "inb001.dat"));
}

TEST_CASE("an APCS_MEMORY_LIMIT that is no byte count is a usage error, exit 2", "[cli][memory]")
{
    const TempFolder folder;
    folder.write("way.dat", "0 0 0\n1 1 0\n2 0 0\n");
    const MemoryLimitVariable limit("lots");
    const auto refused = run_apcs({"path", (folder / "way.dat").string()});
    CHECK(refused.status == 2);
    CHECK(refused.err == "APCS_MEMORY_LIMIT: expected a byte count above 0 such as 4294967296, 512M or 4G; found 'lots'\n");
}

TEST_CASE("an empty APCS_MEMORY_LIMIT means unset, as an empty APCS_DATA does", "[cli][memory]")
{
    // Issue 33: APCS_MEMORY_LIMIT='' was exit 2.
    const TempFolder folder;
    folder.write("way.dat", "0 0 0\n1 1 0\n2 0 0\n");
    const MemoryLimitVariable limit("");
    const auto run = run_apcs({"path", (folder / "way.dat").string()});
    CHECK(run.status == 0);
    CHECK(run.err.empty());
}

TEST_CASE("a key script over 16 MiB is refused before it is read, exit 1", "[cli][memory]")
{
    const TempFolder folder;
    const std::filesystem::path script = folder.write("huge.keys", "ENTER\n");
    std::filesystem::resize_file(script, (16u << 20) + 1);
    const auto refused = run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    CHECK(refused.status == 1);
    CHECK(refused.err == script.string() + ": is 16777217 bytes; expected at most 16777216 bytes (16 MiB)\n");
}
