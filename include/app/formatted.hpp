// Text of numbers for messages, reports and files: one printf-style formatter for the app
// library, so that every message formats numbers the same way and no caller sizes a buffer.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace num::app {

/// The text std::printf(format, ...) would print, e.g. formatted("%.3g s", t); never cut short.
[[gnu::format(printf, 1, 2)]] inline std::string formatted(const char* format, ...) {
    std::va_list args, again;
    va_start(args, format);
    va_copy(again, args);
    const int length = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::string text(length > 0 ? std::size_t(length) : 0, '\0');
    if (length > 0) std::vsnprintf(text.data(), text.size() + 1, format, again);
    va_end(again);
    return text;
}

}  // namespace num::app
