// The USDA text reader: USD's text layer format (and the equivalent `#sdf` cookie) into a Layer.
//
// Grammar follows the Sdf text file format as written by OpenUSD: the header line, an optional
// layer metadata block, and prim specs (`def`/`over`/`class`, optional type, name, optional
// metadata, body) nested to any depth. Bodies hold attributes (with `custom`/`uniform`, every
// value type USD defines, arrays, `.timeSamples`, `.connect`), relationships, variant sets,
// `reorder` statements and child prims. Comments (`#`, `//`, `/* */`) are skipped.
//
// Every syntax error throws usd::ParseError, whose message starts with "file:line:column: ".
// The parser never crashes or hangs on malformed input: it is fuzzed in tests.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "scene/layer.h"

namespace fluence::usd {

class ParseError : public std::runtime_error {
public:
    ParseError(SourceLocation location, const std::string& message);
    const SourceLocation& location() const { return location_; }
    const std::string& message() const { return message_; }

private:
    SourceLocation location_;
    std::string message_;
};

// Raised when a layer file cannot be opened or read.
class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Parses USDA text. `identifier` names the source in error messages (a file path).
std::unique_ptr<Layer> parseUsdaString(std::string_view text, const std::string& identifier);

// Reads and parses a file; throws FileError when it cannot be read, ParseError on bad syntax.
std::unique_ptr<Layer> parseUsdaFile(const std::string& path);

}  // namespace fluence::usd
