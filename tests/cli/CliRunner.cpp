#include "CliRunner.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace specula::test {
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path)
{
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

int CliResult::errorLines() const
{
    std::istringstream lines(err);
    std::string line;
    int count = 0;
    while (std::getline(lines, line))
        if (line.rfind("info:", 0) != 0 && line.rfind("warning:", 0) != 0) ++count;
    return count;
}

CliResult runCli(const std::string& arguments)
{
    // One capture directory per process: ctest runs tests in parallel processes.
    static int call = 0;
    const fs::path dir = fs::temp_directory_path() / ("specula-cli-capture-" + std::to_string(::getpid()) + "-" + std::to_string(++call));
    fs::create_directories(dir);
    const fs::path out = dir / "stdout", err = dir / "stderr";
    const std::string command = std::string(SPECULA_CLI_PATH) + " " + arguments + " </dev/null >" + out.string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    CliResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = slurp(out);
    result.err = slurp(err);
    fs::remove_all(dir);
    return result;
}

std::string tempDir(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("specula-cli-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

} // namespace specula::test
