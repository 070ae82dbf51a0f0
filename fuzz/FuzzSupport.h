#pragma once
// What the fuzzers share: the load options they run under, and quiet logging.
#include "scene/LoadOptions.h"

namespace specula::fuzz {

/// Limits well inside libFuzzer's memory limit (-rss_limit_mb=2560): the fuzzers check that
/// nothing goes wrong inside the limits, and that the limits hold; the defaults would let one
/// input allocate gigabytes legitimately.
scene::LoadOptions loadOptions();

/// Once per process: only errors are logged (the warnings of broken inputs would flood the output).
void quietLogs();

} // namespace specula::fuzz
