// Number text in USDA (internal to the scene library): its syntax,
//   -?(digits[.digits*] | .digits)([eE][+-]?digits)?
// and its value, the correctly rounded double (the one std::from_chars gives), read in one pass.
#pragma once

namespace fluence::usd::detail {

struct ParsedNumber {
    const char* end = nullptr;  // past the number; the start when there is none
    bool integral = false;      // digits only: no '.' and no exponent
    bool inRange = true;        // false when the magnitude is past the double range
    double value = 0.0;
};

// The number at the start of [first, last); an exponent only counts when digits follow its 'e'.
// Decimals of up to 19 digits whose digits form an integer up to 2^53, scaled by a power of ten
// up to 1e22, take one exact multiplication or division, hence a single rounding (Clinger's fast
// path); the others go through std::from_chars.
ParsedNumber parseNumber(const char* first, const char* last);

}  // namespace fluence::usd::detail
