#pragma once
// Runs the specula binary and captures exit code, stdout and stderr.
#include <string>

namespace specula::test {

struct CliResult {
    int exitCode = -1;
    std::string out;
    std::string err;
    /// Lines of stderr that are not log lines of level info/warning.
    int errorLines() const;
};

/// `arguments` is appended to the binary path as a shell command line.
CliResult runCli(const std::string& arguments);

/// A fresh temporary directory for one test.
std::string tempDir(const std::string& name);

} // namespace specula::test
