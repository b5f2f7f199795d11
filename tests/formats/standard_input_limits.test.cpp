#include "apcs/formats/file_io.h"

#include <catch2/catch.hpp>

#include <csignal>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

using namespace apcs;

namespace {

// Standard input fed by a child that writes `piece` again and again (256 MiB at most) and is
// ended when the reading is done. Whether the child was still writing then: a stream read to its
// end lets it finish first.
class EndlessStandardInput {
public:
    explicit EndlessStandardInput(const std::string& piece)
    {
        int ends[2];
        REQUIRE(::pipe(ends) == 0);
        m_writer = ::fork();
        REQUIRE(m_writer >= 0);
        if (m_writer == 0) {
            ::close(ends[0]);
            std::string block;
            while (block.size() < (1u << 16))
                block += piece;
            for (std::size_t written = 0; written < (std::size_t{256} << 20); written += block.size())
                if (::write(ends[1], block.data(), block.size()) < 0)
                    ::_exit(2);
            ::_exit(0);
        }
        ::close(ends[1]);
        m_saved = ::dup(STDIN_FILENO);
        ::dup2(ends[0], STDIN_FILENO);
        ::close(ends[0]);
    }
    EndlessStandardInput(const EndlessStandardInput&) = delete;
    EndlessStandardInput& operator=(const EndlessStandardInput&) = delete;
    ~EndlessStandardInput() { stop(); }

    // Whether the writer had finished all 256 MiB: the reader read to the end.
    bool writer_finished()
    {
        stop();
        return WIFEXITED(m_status) && WEXITSTATUS(m_status) == 0;
    }

private:
    void stop()
    {
        if (m_saved < 0)
            return;
        ::dup2(m_saved, STDIN_FILENO);
        ::close(m_saved);
        m_saved = -1;
        int status = 0;
        if (::waitpid(m_writer, &status, WNOHANG) == 0) {
            ::kill(m_writer, SIGKILL);
            ::waitpid(m_writer, &status, 0);
        }
        m_status = status;
    }

    pid_t m_writer = -1;
    int m_saved = -1;
    int m_status = 0;
};

} // namespace

TEST_CASE("standard input has a file's line limit as it is read: a line that never ends is refused at 4096 bytes",
          "[formats][limits]")
{
    // Issue 33: `yes 1 | tr -d '\n' | apcs path -` read 1 GiB (1.05 GB of memory) before refusing.
    EndlessStandardInput input("1");
    const Expected<DatFile> read = read_dat_file("-");
    REQUIRE_FALSE(read);
    CHECK(read.error().to_string() == "standard input:1: line is more than 4096 bytes long; expected at most 4096");
    CHECK_FALSE(input.writer_finished());
}

TEST_CASE("standard input has a file's point limit as it is read: 10^6 points and no more", "[formats][limits]")
{
    // Issue 33: `yes '0 0 0' | apcs path -` peaked at 2.1 GB.
    EndlessStandardInput input("0 0 0\n; a comment line is no point\n");
    const Expected<DatFile> read = read_dat_file("-");
    REQUIRE_FALSE(read);
    CHECK(read.error().message == "more than 1000000 points; expected at most that many");
    CHECK_FALSE(input.writer_finished());
}

TEST_CASE("a scene or key script from standard input has the line limit too (play -, --keys -)", "[formats][limits]")
{
    // Issue 33: `play -` read a 300 MB line whole (590 MB of memory) before refusing it.
    EndlessStandardInput input("1");
    const Expected<std::string> read = read_script_text("-");
    REQUIRE_FALSE(read);
    CHECK(read.error().to_string() == "standard input:1: line is more than 4096 bytes long; expected at most 4096");
    CHECK_FALSE(input.writer_finished());
}
