#include "sim/world/error.h"

#include <utility>

namespace forcelab::sim {

Error keyError(std::string keyPath, std::string message)
{
    Error e;
    e.keyPath = std::move(keyPath);
    e.message = std::move(message);
    return e;
}

std::string toString(const Error& e)
{
    std::string text = e.source;
    if (!text.empty() && e.line > 0) {
        text.append(":").append(std::to_string(e.line));
        if (e.column > 0)
            text.append(":").append(std::to_string(e.column));
    }
    if (!e.keyPath.empty())
        text.append(text.empty() ? "" : ": ").append(e.keyPath);
    text.append(text.empty() ? "" : ": ").append(e.message);
    return text;
}

InvalidInput::InvalidInput(Error error)
    : std::invalid_argument(toString(error)), m_error(std::move(error))
{
}

} // namespace forcelab::sim
