// Prints each distinct warning once, on stderr, as "fluence: warning: <where>: <message>".
#pragma once

#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fluence::app {

class WarningLog {
public:
    void operator()(const std::string& where, const std::string& message) {
        if (!seen_.insert(where + '\x1f' + message).second) return;
        std::fprintf(stderr, "fluence: warning: %s: %s\n", where.c_str(), message.c_str());
        entries_.emplace_back(where, message);
    }
    std::size_t count() const { return seen_.size(); }
    // Every distinct warning, in the order they were first given: {where, message}.
    const std::vector<std::pair<std::string, std::string>>& entries() const { return entries_; }

private:
    std::set<std::string> seen_;
    std::vector<std::pair<std::string, std::string>> entries_;
};

}  // namespace fluence::app
