// The scene tests' check of a USDA syntax error: parsing `text` as "test.usda" must throw a
// ParseError at line:column whose message contains `message`.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "scene/usda_parser.h"

namespace fluence::test {

inline void expectParseError(const std::string& text, int line, int column, const std::string& message) {
    try {
        usd::parseUsdaString(text, "test.usda");
        ADD_FAILURE() << "no error for:\n" << text;
    } catch (const usd::ParseError& error) {
        std::string prefix = "test.usda:" + std::to_string(line) + ":" + std::to_string(column) + ": ";
        EXPECT_EQ(std::string(error.what()).substr(0, prefix.size()), prefix) << error.what();
        EXPECT_EQ(error.location().file, "test.usda");
        EXPECT_EQ(error.location().line, line) << error.what();
        EXPECT_EQ(error.location().column, column) << error.what();
        EXPECT_NE(error.message().find(message), std::string::npos)
            << "message: " << error.message() << "\nexpected to contain: " << message;
    }
}

}  // namespace fluence::test
