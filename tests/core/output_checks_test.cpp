// The checks of a program's outputs before its work (core/output_checks.hpp).
#include <gtest/gtest.h>

#include <fstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/output_checks.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;
namespace fs = std::filesystem;

TEST(OutputChecks, AnOutputThatIsAnInputIsAUsageErrorAlsoThroughALink) {
    const fs::path dir = scratch_dir();
    const fs::path input = dir / "in.su2";
    std::ofstream(input) << "NDIME= 2\n";
    fs::create_symlink(input, dir / "link.su2");
    EXPECT_THROW(check_output(input, {input}), UsageError);
    try {
        check_output(dir / "link.su2", {input});
        FAIL() << "a link to the input was taken";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("the same file as the input " + input.string()), std::string::npos)
            << e.what();
    }
    EXPECT_NO_THROW(check_output(dir / "out.su2", {input}));  // not there yet
    EXPECT_NO_THROW(check_output(input, {dir / "other.su2"}));
    EXPECT_THROW(check_output(dir, {}), IoError);  // a folder cannot be replaced by a file
}

TEST(OutputChecks, FoldersMustBeWritableOrMade) {
    const fs::path dir = scratch_dir();
    EXPECT_THROW(check_output_file(dir / "missing" / "out.su2", {}), IoError);
    EXPECT_NO_THROW(check_nearest_folder_writable(dir / "missing" / "deeper"));  // made later, under dir
    make_output_folder(dir / "made" / "here");
    EXPECT_TRUE(fs::is_directory(dir / "made" / "here"));
    EXPECT_NO_THROW(check_output_file(dir / "made" / "here" / "out.su2", {}));
    std::ofstream(dir / "file") << "x";
    EXPECT_THROW(make_output_folder(dir / "file" / "sub"), IoError);
}
