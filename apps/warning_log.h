// Prints each distinct warning once, on stderr, as "fluence: warning: <where>: <message>".
#pragma once

#include <cstdio>
#include <set>
#include <string>

namespace fluence::app {

class WarningLog {
public:
    void operator()(const std::string& where, const std::string& message) {
        if (seen_.insert(where + '\x1f' + message).second)
            std::fprintf(stderr, "fluence: warning: %s: %s\n", where.c_str(), message.c_str());
    }
    std::size_t count() const { return seen_.size(); }

private:
    std::set<std::string> seen_;
};

}  // namespace fluence::app
