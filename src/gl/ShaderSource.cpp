#include "gl/ShaderSource.h"

#include <fstream>
#include <regex>
#include <sstream>

#include "core/Error.h"
#include "gl/EmbeddedShaders.h"

namespace specula::gl {
namespace fs = std::filesystem;
namespace {

// Line numbers carry the file too: "#line (file * kLineStride + line) file". Mesa reports
// the source-string number inconsistently (some errors say 0 whatever the #line said), the
// line number it always keeps.
constexpr long kLineStride = 100000;

std::string lineDirective(int line, int file)
{
    return fmt::format("#line {} {}\n", long(file) * kLineStride + line, file);
}

struct Loader {
    fs::path root; // empty: the copy embedded in the library
    std::vector<std::string> files;  // relative paths, index = source-string number
    std::vector<std::string> stack;  // for cycle reports
    std::string out;
    std::string defines;
    bool sawVersion = false;

    static std::string readFile(const fs::path& path)
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) return {};
        std::ostringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }

    bool exists(const std::string& relative) const
    {
        if (root.empty()) return findEmbeddedShader(relative) != nullptr;
        std::error_code ec;
        return fs::is_regular_file(root / relative, ec);
    }

    std::string read(const std::string& relative) const
    {
        if (root.empty()) return std::string(findEmbeddedShader(relative)->text);
        return readFile(root / relative);
    }

    int fileIndex(const std::string& name)
    {
        for (size_t i = 0; i < files.size(); ++i)
            if (files[i] == name) return int(i);
        files.push_back(name);
        return int(files.size() - 1);
    }

    void load(const std::string& relative, const std::string& includer, int includerLine)
    {
        for (size_t i = 0; i < stack.size(); ++i) {
            if (stack[i] == relative) {
                std::string cycle;
                for (size_t j = i; j < stack.size(); ++j) cycle += stack[j] + " -> ";
                throw Error("shader include cycle: {}{}", cycle, relative);
            }
        }
        if (!exists(relative)) {
            if (includer.empty())
                throw Error("shader file not found: {}", root.empty() ? "(embedded) " + relative : (root / relative).string());
            throw Error("shaders/{}:{}: cannot include \"{}\": file not found", includer, includerLine, relative);
        }
        const std::string text = read(relative);
        stack.push_back(relative);
        const int index = fileIndex(relative);
        // Include once, decided by the GLSL preprocessor: a guard per file. The loader cannot
        // skip a second include itself, as it does not evaluate #if: a file first included in
        // a branch the preprocessor drops would then be missing where it is included again.
        const bool included = stack.size() > 1;
        if (included) out += fmt::format("#ifndef SPECULA_INCLUDED_{0}\n#define SPECULA_INCLUDED_{0}\n", index);

        std::istringstream lines(text);
        std::string line;
        int lineNumber = 0;
        static const std::regex includeRe(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
        static const std::regex versionRe(R"(^\s*#\s*version\b.*)");
        out += lineDirective(1, index);
        while (std::getline(lines, line)) {
            ++lineNumber;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::smatch match;
            if (std::regex_match(line, match, versionRe)) {
                if (sawVersion || stack.size() > 1)
                    throw Error("shaders/{}:{}: #version is only allowed in the main file", relative, lineNumber);
                sawVersion = true;
                // #version must come first: drop the #line we emitted before it.
                out.clear();
                out += line + "\n" + defines;
                out += lineDirective(lineNumber + 1, index);
                continue;
            }
            if (std::regex_match(line, match, includeRe)) {
                const std::string name = match[1].str();
                // Relative to the including file, then to the root.
                const fs::path local = fs::path(relative).parent_path() / name;
                std::string resolved = local.lexically_normal().generic_string();
                if (!exists(resolved)) resolved = fs::path(name).lexically_normal().generic_string();
                load(resolved, relative, lineNumber);
                out += lineDirective(lineNumber + 1, index);
                continue;
            }
            out += line;
            out += '\n';
        }
        if (included) out += "#endif\n";
        stack.pop_back();
    }
};

} // namespace

ShaderSource loadShaderSource(const fs::path& root, const std::string& path, const std::vector<std::string>& defines)
{
    Loader loader;
    loader.root = root;
    for (const auto& define : defines) loader.defines += "#define " + define + "\n";
    loader.load(fs::path(path).lexically_normal().generic_string(), {}, 0);
    if (!loader.sawVersion) throw Error("shaders/{}: missing #version", path);
    return {std::move(loader.out), std::move(loader.files)};
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files)
{
    // Mesa: "0:12(5): error: ..."   NVIDIA: "0(12) : error C0000: ..."
    static const std::regex mesaRe(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvidiaRe(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    // glslangValidator: "ERROR: 0:12: ..."
    static const std::regex glslangRe(R"(^(?:ERROR|WARNING): (\d+):(\d+): (.*)$)");
    std::istringstream lines(log);
    std::string line;
    std::string out;
    while (std::getline(lines, line)) {
        std::smatch match;
        std::string mapped = line;
        if (std::regex_match(line, match, mesaRe) || std::regex_match(line, match, nvidiaRe) ||
            std::regex_match(line, match, glslangRe)) {
            size_t index = std::stoul(match[1].str());
            long lineNumber = std::stol(match[2].str());
            if (lineNumber >= kLineStride) {
                index = size_t(lineNumber / kLineStride);
                lineNumber %= kLineStride;
            }
            const std::string name = index < files.size() ? "shaders/" + files[index] : "shader " + std::to_string(index);
            mapped = fmt::format("{}:{}: {}", name, lineNumber, match[match.size() - 1].str());
        }
        if (!mapped.empty()) out += mapped + "\n";
    }
    if (!out.empty() && out.back() == '\n') out.pop_back();
    return out;
}

} // namespace specula::gl
