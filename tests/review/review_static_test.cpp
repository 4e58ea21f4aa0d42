// apps/review_static.h and `fluence review --static`: a file the export cannot read is a clear
// error naming it (not the review API's JSON error body), with a non-zero exit.
#include "apps/review_static.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "apps/review_api.h"
#include "apps/review_command.h"
#include "apps/review_files.h"
#include "apps/scene_loading.h"
#include "tests/support/temp_dir.h"

namespace fluence::app {
namespace {

TEST(ReviewStatic, AnUnreadableImageIsAnErrorNamingItNotAJsonBody) {
    test::TempDir dir;
    const std::filesystem::path bad = dir.path() / "broken.exr";
    std::ofstream(bad) << "not an OpenEXR file";
    const ReviewApi api(expandReviewPaths({bad.string()}));
    try {
        writeStaticReview(api, (dir.path() / "page").string());
        FAIL() << "the export of an unreadable image succeeded";
    } catch (const ReviewInputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("broken.exr"), std::string::npos) << message;
        EXPECT_NE(message.front(), '{') << message;
        EXPECT_EQ(message.find("\"error\""), std::string::npos) << message;
    }
    ReviewOptions options;
    options.paths = {bad.string()};
    options.staticDir = (dir.path() / "page").string();
    EXPECT_EQ(runReview(options), kExitMissingInput);
}

}  // namespace
}  // namespace fluence::app
