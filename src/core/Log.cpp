#include "core/Log.h"

#include <cstdlib>
#include <mutex>

#include <spdlog/sinks/stdout_color_sinks.h>

namespace specula::log {

void init()
{
    static std::once_flag once;
    std::call_once(once, [] {
        auto logger = spdlog::stderr_color_mt("specula");
        logger->set_pattern("%^%l%$: %v");
        spdlog::set_default_logger(logger);
        spdlog::set_level(spdlog::level::info);
        if (const char* level = std::getenv("SPECULA_LOG")) {
            spdlog::set_level(spdlog::level::from_str(level));
        }
    });
}

} // namespace specula::log
