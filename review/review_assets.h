// The review page's files (review/web/), embedded into the binary at build time by
// review/CMakeLists.txt, so `fluence review` and its static export work from any install.
#pragma once

#include <vector>

namespace fluence::review {

struct ReviewAsset {
    const char* name;         // "index.html", "review.js", "review.css"
    const char* contentType;  // its MIME type
    const char* text;
};

const std::vector<ReviewAsset>& reviewAssets();

}  // namespace fluence::review
