#include "texture/ies_file.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fluence::texture {

namespace {

// The numbers after TILT=, each with the line it is on.
class NumberStream {
public:
    NumberStream(const std::string& name, std::istream& in, int firstLine) : name_(name), in_(in), line_(firstLine) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw IesFileError(name_ + ":" + std::to_string(line_) + ": " + what);
    }

    double next(const char* what) {
        while (tokens_.empty()) {
            std::string text;
            if (!std::getline(in_, text)) fail(std::string("the file ends before ") + what);
            ++line_;
            for (char& c : text)
                if (c == ',' || c == '\r' || c == '\t') c = ' ';
            std::istringstream words(text);
            std::string word;
            while (words >> word) tokens_.push_back(word);
            index_ = 0;
            if (tokens_.empty()) continue;
        }
        const std::string word = tokens_[index_++];
        if (index_ == tokens_.size()) tokens_.clear();
        char* end = nullptr;
        double value = std::strtod(word.c_str(), &end);
        if (end == word.c_str() || *end != '\0' || !std::isfinite(value))
            fail("'" + word + "' is not a number (" + what + ")");
        return value;
    }

    int count(const char* what, int least) {
        double v = next(what);
        if (v != std::floor(v) || v < least || v > 100000)
            fail(std::string(what) + " " + std::to_string(v) + " is not a count");
        return static_cast<int>(v);
    }

    std::vector<float> increasing(int n, const char* what) {
        std::vector<float> values(n);
        for (int i = 0; i < n; ++i) {
            values[i] = static_cast<float>(next(what));
            if (i > 0 && !(values[i] > values[i - 1])) fail(std::string(what) + " do not increase");
        }
        return values;
    }

    bool atEnd() {
        std::string rest;
        while (tokens_.empty() && std::getline(in_, rest)) {
            ++line_;
            if (rest.find_first_not_of(" \t\r,\x1a") != std::string::npos) return false;
        }
        return tokens_.empty();
    }

private:
    const std::string& name_;
    std::istream& in_;
    int line_;
    std::vector<std::string> tokens_;
    std::size_t index_ = 0;
};

bool near(float a, float b) { return std::abs(a - b) < 1e-3f; }

void checkTypeCAngles(const IesTable& t, NumberStream& numbers) {
    const std::vector<float>& v = t.verticalDegrees;
    const std::vector<float>& h = t.horizontalDegrees;
    bool verticalOk =
        (near(v.front(), 0.0f) || near(v.front(), 90.0f)) && (near(v.back(), 90.0f) || near(v.back(), 180.0f));
    if (!verticalOk) numbers.fail("type C vertical angles must run 0-90, 90-180 or 0-180 degrees");
    bool single = h.size() == 1 && near(h[0], 0.0f);
    bool fromZero =
        near(h.front(), 0.0f) && (near(h.back(), 90.0f) || near(h.back(), 180.0f) || near(h.back(), 360.0f));
    bool lateral = near(h.front(), 90.0f) && near(h.back(), 270.0f);
    if (!single && !fromZero && !lateral)
        numbers.fail("type C horizontal angles must be 0, 0-90, 0-180, 90-270 or 0-360 degrees");
}

void skipTiltData(NumberStream& numbers) {
    numbers.count("the lamp-to-luminaire geometry", 1);
    int n = numbers.count("the number of tilt angles", 0);
    numbers.increasing(n, "the tilt angles");
    for (int i = 0; i < n; ++i) numbers.next("the tilt multiplying factors");
}

}  // namespace

IesTable parseIes(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    IesTable table;
    std::string line;
    int lineNumber = 0;
    bool tilt = false;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (lineNumber == 1 && line.starts_with("IESNA")) table.standard = line;
        if (line.starts_with("TILT=")) {
            tilt = true;
            break;
        }
    }
    if (!tilt) throw IesFileError(name + ":" + std::to_string(lineNumber) + ": no TILT= line: not an IES LM-63 file");
    NumberStream numbers(name, in, lineNumber);
    std::string tiltValue = line.substr(5);
    while (!tiltValue.empty() && tiltValue.back() == ' ') tiltValue.pop_back();
    if (tiltValue == "INCLUDE")
        skipTiltData(numbers);
    else if (tiltValue != "NONE")
        numbers.fail("TILT=" + tiltValue + ": tilt data in another file is not supported (TILT=NONE or INCLUDE)");

    numbers.count("the number of lamps", 0);
    numbers.next("the lumens per lamp");
    double multiplier = numbers.next("the candela multiplier");
    int verticalCount = numbers.count("the number of vertical angles", 1);
    int horizontalCount = numbers.count("the number of horizontal angles", 1);
    int type = numbers.count("the photometric type", 1);
    if (type != 1)
        numbers.fail("photometric type " +
                     std::string(type == 2   ? "B"
                                 : type == 3 ? "A"
                                             : "?") +
                     " (" + std::to_string(type) + ") is not supported: only type C (1)");
    numbers.count("the units type", 1);
    for (const char* what : {"the width", "the length", "the height", "the ballast factor",
                             "the ballast-lamp photometric factor", "the input watts"})
        numbers.next(what);
    table.verticalDegrees = numbers.increasing(verticalCount, "the vertical angles");
    table.horizontalDegrees = numbers.increasing(horizontalCount, "the horizontal angles");
    checkTypeCAngles(table, numbers);
    table.candela.resize(std::size_t(verticalCount) * horizontalCount);
    for (float& c : table.candela) {
        c = static_cast<float>(numbers.next("the candela values") * multiplier);
        if (c < 0.0f) numbers.fail("a negative candela value");
    }
    if (!numbers.atEnd()) numbers.fail("numbers follow the candela values");
    return table;
}

IesTable readIesFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw IesFileError(path + ": cannot be opened");
    std::ostringstream text;
    text << file.rdbuf();
    return parseIes(text.str(), path);
}

}  // namespace fluence::texture
