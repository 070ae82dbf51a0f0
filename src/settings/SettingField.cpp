#include "settings/SettingField.h"

#include <cctype>

#include <fmt/format.h>

namespace specula {

std::string SettingRange::requirement() const
{
    if (isAny()) return "must be a finite number";
    if (bounded()) return fmt::format("must be between {} and {}", min, max);
    if (std::isfinite(min) && std::isinf(max)) {
        if (min == 0.0) return minExclusive ? "must be positive" : "must not be negative";
        return minExclusive ? fmt::format("must be greater than {}", min) : fmt::format("must be at least {}", min);
    }
    return fmt::format("must be at most {}", max);
}

std::string SettingRange::span() const
{
    return bounded() ? fmt::format("{} to {}", min, max) : std::string();
}

std::string kebabCase(std::string_view camelCase)
{
    std::string out;
    for (char c : camelCase) {
        if (std::isupper(static_cast<unsigned char>(c))) {
            out += '-';
            out += char(std::tolower(static_cast<unsigned char>(c)));
        } else {
            out += c;
        }
    }
    return out;
}

std::string words(std::string_view camelCase)
{
    std::string out = kebabCase(camelCase);
    std::replace(out.begin(), out.end(), '-', ' ');
    return out;
}

std::string flagName(std::string_view passKey, std::string_view fieldName)
{
    const std::string pass = kebabCase(passKey);
    return fieldName == "enabled" ? pass : pass + "-" + kebabCase(fieldName);
}

std::string formatSetting(SettingKind kind, double value)
{
    if (kind == SettingKind::Bool) return value != 0.0 ? "on" : "off";
    // As a float: the member's own value (0.025f prints 0.025, not 0.02500000037252903).
    if (kind == SettingKind::Float) return fmt::format("{}", float(value));
    return fmt::format("{}", value);
}

std::string commandLineHelp(SettingKind kind, const char* help, const SettingRange& range, double defaultValue)
{
    const std::string value = formatSetting(kind, defaultValue);
    if (kind == SettingKind::Bool) return fmt::format("{}: on or off (default {})", help, value);
    const std::string span = range.span();
    return span.empty() ? fmt::format("{} (default {})", help, value) : fmt::format("{}, {} (default {})", help, span, value);
}

} // namespace specula
