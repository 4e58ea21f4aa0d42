// `fluence review --static OUT_DIR`: the review page as plain files that open from disk (file://)
// or from any web server: index.html, review.js, review.css and data.js, which holds every answer
// the page can ask for (apps/review_api.h: each image, each layer's pixels in base64, each
// display/view/look shader of the file's OCIO config), keyed "REQUEST|ARG|ARG...".
#pragma once

#include <string>

#include "apps/review_api.h"

namespace fluence::app {

// Writes the folder (created if missing), each file atomically. Throws output::OutputError or
// ReviewInputError naming the file.
void writeStaticReview(const ReviewApi& api, const std::string& outputDir);

}  // namespace fluence::app
