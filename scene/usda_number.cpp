#include "scene/usda_number.h"

#include <charconv>
#include <cstdint>
#include <system_error>

namespace fluence::usd::detail {

namespace {

bool isDigit(const char* p, const char* last) { return p < last && *p >= '0' && *p <= '9'; }

// Every power of ten a double holds exactly.
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kMaxExactPower = 22;
constexpr std::uint64_t kMaxExactInteger = std::uint64_t(1) << 53;
constexpr int kMaxDigits = 19;  // any 19 digits fit in 64 bits

}  // namespace

ParsedNumber parseNumber(const char* first, const char* last) {
    const char* p = first;
    bool negative = p < last && *p == '-';
    if (negative) ++p;
    if (!isDigit(p, last) && !(p < last && *p == '.' && isDigit(p + 1, last))) return {first};
    // The digits, before and after the '.', as one integer (it wraps past kMaxDigits digits,
    // which then go through from_chars).
    std::uint64_t digits = 0;
    const char* start = p;
    for (; isDigit(p, last); ++p) digits = digits * 10 + static_cast<unsigned>(*p - '0');
    long count = p - start;
    ParsedNumber number;
    number.integral = true;
    int exponent = 0;  // the value is digits * 10^exponent
    if (p < last && *p == '.') {
        number.integral = false;
        start = ++p;
        for (; isDigit(p, last); ++p) digits = digits * 10 + static_cast<unsigned>(*p - '0');
        count += p - start;
        exponent = -static_cast<int>(p - start);
    }
    if (p < last && (*p == 'e' || *p == 'E')) {
        const char* q = p + 1;
        bool negativeExponent = q < last && *q == '-';
        if (q < last && (*q == '-' || *q == '+')) ++q;
        if (isDigit(q, last)) {
            number.integral = false;
            int written = 0;
            for (start = q; isDigit(q, last); ++q) {
                if (q - start < 6) written = written * 10 + (*q - '0');
            }
            exponent += negativeExponent ? -written : written;
            p = q;
        }
    }
    number.end = p;
    if (count <= kMaxDigits && digits == 0) {
        number.value = negative ? -0.0 : 0.0;
    } else if (count <= kMaxDigits && digits <= kMaxExactInteger && exponent >= -kMaxExactPower &&
               exponent <= kMaxExactPower) {
        double value = static_cast<double>(digits);
        value = exponent < 0 ? value / kExactPowersOfTen[-exponent] : value * kExactPowersOfTen[exponent];
        number.value = negative ? -value : value;
    } else {
        number.inRange = std::from_chars(first, p, number.value).ec != std::errc::result_out_of_range;
    }
    return number;
}

}  // namespace fluence::usd::detail
