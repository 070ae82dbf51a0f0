#include "scene/LoadOptions.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

namespace specula::scene {

namespace fs = std::filesystem;

namespace {

/// RFC 3986 scheme: a letter, then letters, digits, '+', '-', '.', then ':'. One letter is
/// allowed too (there are no drive letters on the platforms we build for).
bool hasScheme(std::string_view reference)
{
    const size_t colon = reference.find(':');
    if (colon == std::string_view::npos || colon == 0) return false;
    if (!std::isalpha(static_cast<unsigned char>(reference[0]))) return false;
    return std::all_of(reference.begin(), reference.begin() + std::ptrdiff_t(colon), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    });
}

/// `path` is `root` or below it, component by component (both already canonical).
bool isInside(const fs::path& path, const fs::path& root)
{
    auto p = path.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++p) {
        if (r->empty()) continue; // a trailing separator
        if (p == path.end() || *p != *r) return false;
    }
    return true;
}

} // namespace

std::optional<std::string> refuseReference(const fs::path& root, std::string_view reference, bool allowExternal)
{
    if (hasScheme(reference)) return std::string("is a URI scheme Specula does not open (only relative paths and data: URIs)");
    if (allowExternal) return std::nullopt;
    const fs::path path(reference);
    if (path.is_absolute()) return std::string("is an absolute path");
    // Symbolic links are followed: a link inside the folder to a file outside it is outside.
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(root.empty() ? fs::path(".") : root, ec);
    if (ec) return fmt::format("cannot be resolved ({})", ec.message());
    const fs::path resolved = fs::weakly_canonical(base / path, ec);
    if (ec) return fmt::format("cannot be resolved ({})", ec.message());
    if (!isInside(resolved, base)) return std::string("leaves the folder of the file that names it");
    return std::nullopt;
}

} // namespace specula::scene
