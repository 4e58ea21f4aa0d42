// The Unicode identifier classes of UAX #31 that USD names are made of (internal to the scene
// library): an identifier is an XID_Start character or '_', then XID_Continue characters
// (OpenUSD's TfIsValidIdentifier and SdfPath rules since its UTF-8 support).
#pragma once

namespace fluence::usd::detail {

bool isXidStart(char32_t codePoint);     // letters: A-Z, a-z, 'é', '㤼', ...
bool isXidContinue(char32_t codePoint);  // XID_Start plus digits, '_', combining marks, ...

}  // namespace fluence::usd::detail
