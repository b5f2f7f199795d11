#include "apcs/formats/key_file_guard.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace apcs;
using test::TempFolder;

namespace fs = std::filesystem;

TEST_CASE("a key file is guarded under its own name and nothing else is", "[formats][key-file-guard]")
{
    const TempFolder folder;
    const fs::path key = folder.write("key1.dat", "0 0\n1 1\n");
    const fs::path other = folder.write("way1.dat", "0 0\n1 1\n");
    KeyFileGuard guard;
    guard.protect(key);
    REQUIRE(guard.guards(key));
    REQUIRE_FALSE(guard.guards(other));
    REQUIRE_FALSE(guard.guards(folder / "inb001.dat"));
    REQUIRE(guard.may_write(other).has_value());
}

TEST_CASE("refusing a key file names the target and says why", "[formats][key-file-guard]")
{
    const TempFolder folder;
    const fs::path key = folder.write("key1.dat", "0 0\n1 1\n");
    KeyFileGuard guard;
    guard.protect(key);
    const Expected<void> refusal = guard.may_write(key);
    REQUIRE_FALSE(refusal.has_value());
    REQUIRE(refusal.error().to_string() == key.string() + ": is a key file; key files are never written");
}

TEST_CASE("a hard link to a key file is the key file", "[formats][key-file-guard]")
{
    const TempFolder folder;
    const fs::path key = folder.write("key1.dat", "0 0\n1 1\n");
    fs::create_hard_link(key, folder / "inb001.dat");
    KeyFileGuard guard;
    guard.protect(key);
    REQUIRE(guard.guards(folder / "inb001.dat"));
}

TEST_CASE("a symbolic link to a key file, or a key file reached through one, is the key file",
          "[formats][key-file-guard]")
{
    const TempFolder folder;
    const fs::path key = folder.write("key1.dat", "0 0\n1 1\n");
    fs::create_symlink(key, folder / "inb001.dat");
    KeyFileGuard guard;
    guard.protect(folder / "inb001.dat");
    REQUIRE(guard.guards(key));
    KeyFileGuard guard_of_target;
    guard_of_target.protect(key);
    REQUIRE(guard_of_target.guards(folder / "inb001.dat"));
}

TEST_CASE("a name in another case is the key file, as on DOS", "[formats][key-file-guard]")
{
    const TempFolder folder;
    const fs::path key = folder.write("key1.dat", "0 0\n1 1\n");
    SECTION("the key named in capitals finds key1.dat, as reading it did")
    {
        KeyFileGuard guard;
        guard.protect(folder / "KEY1.DAT");
        REQUIRE(guard.guards(key));
    }
    SECTION("a target in capitals that does not exist yet")
    {
        KeyFileGuard guard;
        guard.protect(key);
        REQUIRE(guard.guards(folder / "KEY1.DAT"));
    }
    SECTION("names alone, with no file behind them")
    {
        KeyFileGuard guard;
        guard.protect("KEY2.DAT");
        REQUIRE(guard.guards("./key2.dat"));
        REQUIRE(guard.guards("sub/../Key2.Dat"));
        REQUIRE_FALSE(guard.guards("key3.dat"));
    }
}

TEST_CASE("a relative and an absolute name of one key file are the same file", "[formats][key-file-guard]")
{
    const TempFolder folder;
    const fs::path key = folder.write("key1.dat", "0 0\n1 1\n");
    const fs::path relative = fs::relative(key);
    REQUIRE(relative.is_relative());
    KeyFileGuard guard;
    guard.protect(relative);
    REQUIRE(guard.guards(key));
    KeyFileGuard absolute_guard;
    absolute_guard.protect(key);
    REQUIRE(absolute_guard.guards(relative));
    REQUIRE(absolute_guard.guards(folder.path() / "." / "key1.dat"));
}

TEST_CASE("a guard with no key files guards nothing", "[formats][key-file-guard]")
{
    const TempFolder folder;
    const fs::path file = folder.write("key1.dat", "0 0\n1 1\n");
    REQUIRE_FALSE(KeyFileGuard{}.guards(file));
}
