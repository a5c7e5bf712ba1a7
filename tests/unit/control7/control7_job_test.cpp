// control7's job (lib/control7/control7_job): --answer parsing, the golden deck written
// through run(), answers left after IRPT 0, and warnings for unused overrides.
#include "control7/control7_job.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace sigchain::control7 {
namespace {

const std::string kAnswers = SIGCHAIN_TEST_DATA "/control7/us_standard.answers";
const std::string kGolden = SIGCHAIN_SOURCE_DIR "/tests/golden/control7/us_standard.cdk";

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Warnings : Reporter {
    mutable std::vector<std::string> messages;
    void warn(const std::string& m) const override { messages.push_back(m); }
};

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            (name + "." + std::to_string(::testing::UnitTest::GetInstance()->random_seed())))
        .string();
}

TEST(Control7Job, AnswerOverridesAreKeyValue) {
    const auto m = parse_answer_overrides({"vis=  50 ", "ihaze=1", "vis=23"});
    EXPECT_EQ(m.size(), 2u);
    EXPECT_EQ(m.at("vis"), "23");  // a later KEY wins
    EXPECT_EQ(m.at("ihaze"), "1");
    EXPECT_THROW(parse_answer_overrides({"vis"}), UsageError);
    EXPECT_THROW(parse_answer_overrides({"=50"}), UsageError);
}

TEST(Control7Job, WritesTheGoldenDeck) {
    Control7Job job;
    job.answers_path = kAnswers;
    job.output_path = temp_path("control7_job.cdk");
    run(job, Reporter{});
    EXPECT_EQ(slurp(job.output_path), slurp(kGolden));
    std::filesystem::remove(job.output_path);
}

TEST(Control7Job, AnAnswerAfterTheLastRunIsAnErrorAndWritesNothing) {
    const std::string answers = temp_path("control7_job.answers");
    std::ofstream(answers) << slurp(kAnswers) << "\nextra\n";
    Control7Job job;
    job.answers_path = answers;
    job.output_path = temp_path("control7_job_extra.cdk");
    EXPECT_THROW(run(job, Reporter{}), DataError);
    EXPECT_FALSE(std::filesystem::exists(job.output_path));
    std::filesystem::remove(answers);
}

TEST(Control7Job, WarnsAboutAnOverrideWhoseQuestionIsNotAsked) {
    Control7Job job;
    job.answers_path = kAnswers;
    job.output_path = temp_path("control7_job_warn.cdk");
    job.overrides = {{"rsd", "none.rsd"}};  // the standard model asks for no radiosonde
    Warnings w;
    run(job, w);
    // The override's warning, then one per field build_radiance refuses in this deck
    // (a transmittance run, IEMSCT 0, and the VSA, IVSA 1; its cirrus, ICLD 18, is
    // modelled).
    ASSERT_EQ(w.messages.size(), 3u);
    EXPECT_NE(w.messages[0].find("--answer rsd"), std::string::npos);
    EXPECT_NE(w.messages[1].find("build_radiance will refuse this deck: run 1: CARD 1 IEMSCT"),
              std::string::npos);
    EXPECT_NE(w.messages[2].find("CARD 2 IVSA (columns 26-30)"), std::string::npos);
    std::filesystem::remove(job.output_path);
}

}  // namespace
}  // namespace sigchain::control7
