#pragma once
// One problem with an input (a lesson file, a --set override, a scene built in
// code): where it is and what is wrong. It travels as this struct from the
// simulation's checks through the lesson loader to the command line and the
// workbench's dialogs; only the last step turns it into a line of text.

#include <stdexcept>
#include <string>

namespace forcelab::sim {

struct Error {
    std::string source;  ///< the file, "--set KEY=VALUE", or empty when the input is a scene built in code
    std::string keyPath; ///< the lesson format's key path, e.g. "models.drag.k" or "balls.3.r"; empty for the input as a whole
    int line = 0;        ///< 1-based line in `source`; 0 when not known
    int column = 0;      ///< 1-based column (characters, not bytes); 0 when not known
    std::string message; ///< what is wrong and, where it helps, how to fix it
};

/// A problem at a key path whose source and place the reader fills in later.
Error keyError(std::string keyPath, std::string message);

/// "source:line:column: key.path: message", leaving out the parts that are
/// not known: the one line a user reads.
std::string toString(const Error& error);

/// Thrown where a problem cannot be returned, e.g. by a World constructed
/// from an invalid scene: its what() is toString(error()).
class InvalidInput : public std::invalid_argument {
public:
    explicit InvalidInput(Error error);
    const Error& error() const { return m_error; }

private:
    Error m_error;
};

} // namespace forcelab::sim
