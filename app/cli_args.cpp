#include "cli_args.h"

#include <cmath>
#include <stdexcept>

namespace forcelab::cli {

std::optional<double> parseFiniteNumber(const std::string& text)
{
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(v))
            return std::nullopt;
        return v;
    } catch (const std::logic_error&) { // invalid_argument, out_of_range
        return std::nullopt;
    }
}

} // namespace forcelab::cli
