#pragma once
// Errors a user can cause and fix (missing file, bad model, unsupported GL, bad option).
// The message names the thing and says what to do; `vct` prints it once and exits non-zero.
#include <sstream>
#include <stdexcept>
#include <string>

namespace vct {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Concatenates its arguments with operator<< into one message and throws vct::Error.
template <class... Parts>
[[noreturn]] void fail(const Parts&... parts) {
    std::ostringstream message;
    (message << ... << parts);
    throw Error(message.str());
}

template <class... Parts>
std::string concat(const Parts&... parts) {
    std::ostringstream message;
    (message << ... << parts);
    return message.str();
}

}  // namespace vct
