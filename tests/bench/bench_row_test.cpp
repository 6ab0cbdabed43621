// The bench's rows: which methods it leaves out, the paper's figures beside
// ours, and one row measured on the paper's rectangle.
#include <gtest/gtest.h>

#include "dgwarp/bench/bench_report.hpp"
#include "dgwarp/bench/bench_row.hpp"

using namespace dgwarp;

TEST(BenchRow, SkipsWhatTheLimitsLeaveOut) {
    BenchLimits limits;
    limits.rbf_max_boundary = 100;
    limits.idw_max_work = 1000;
    limits.laplacian_max_nodes = 500;
    EXPECT_EQ(bench_skip_reason(Method::rbf, limits, 200, 100, 2), "");
    EXPECT_EQ(bench_skip_reason(Method::rbf, limits, 200, 101, 2).rfind("skipped: dense 101", 0), 0u);
    EXPECT_EQ(bench_skip_reason(Method::idw, limits, 110, 10, 2), "");     // 100 × 10 = the limit
    EXPECT_NE(bench_skip_reason(Method::idw, limits, 111, 10, 2), "");     // 101 × 10
    EXPECT_EQ(bench_skip_reason(Method::laplacian, limits, 500, 10, 3), "");
    EXPECT_NE(bench_skip_reason(Method::laplacian, limits, 501, 10, 3), "");
    for (Method m : all_methods) EXPECT_EQ(bench_skip_reason(m, BenchLimits{}, 1000, 100, 3), "") << method_name(m);
    limits = {};
    limits.quick = true;
    EXPECT_NE(bench_skip_reason(Method::rbf, limits, 1000, 100, 3), "");
    EXPECT_NE(bench_skip_reason(Method::laplacian, limits, 1000, 100, 3), "");
    EXPECT_EQ(bench_skip_reason(Method::rbf, limits, 1000, 100, 2), "");
    EXPECT_EQ(bench_skip_reason(Method::dg_harmonic, limits, 1000, 100, 3), "");
}

TEST(BenchRow, PaperFiguresOfTable1) {
    const auto entry = paper_entry("rect-box", 0, "rotate-30");
    ASSERT_TRUE(entry);
    EXPECT_EQ(entry->tables, "Tables 1-3");
    const PaperFigures dg_idw = paper_figures(*entry, Method::dg_idw);
    EXPECT_EQ(dg_idw.mean, 0.952);
    EXPECT_EQ(dg_idw.min, 0.784);
    EXPECT_EQ(paper_figures(*entry, Method::rbf).seconds, 0.065);
    EXPECT_FALSE(paper_figures(*entry, Method::dg_harmonic).mean);  // not in the paper
    EXPECT_TRUE(paper_figures(*paper_entry("rect-box", 0, "rotate-90"), Method::dgm).failed);
    EXPECT_FALSE(paper_entry("rect-box", 0, "spin"));
}

TEST(BenchRow, MeasuresEveryMethodAndVariantOnTheRectangle) {
    const Mesh mesh = make_case("rect-box", 0);
    const std::vector<CaseMotion> motions = case_motions("rect-box", mesh);
    const CaseMotion& rotate30 = motions.front();
    ASSERT_EQ(rotate30.name, "rotate-30");
    std::vector<std::string> started, deformed;
    BenchObserver observer;
    observer.started = [&](const std::string& what) { started.push_back(what); };
    observer.deformed = [&](const std::string& label, const Mesh& m, std::span<const double> q) {
        EXPECT_EQ(q.size(), m.cells.size());
        deformed.push_back(label);
    };
    const BenchRow row = measure_motion("rect-box", 0, mesh, rotate30, BenchLimits{}, observer);
    EXPECT_EQ(row.nodes, mesh.num_points());
    EXPECT_GT(row.moving_nodes, 0u);
    EXPECT_LT(row.moving_nodes, row.boundary_nodes);
    ASSERT_TRUE(row.paper);
    ASSERT_EQ(row.methods.size(), std::size(all_methods) + 3);  // and three DG-IDW variants
    EXPECT_EQ(started.size(), row.methods.size());
    EXPECT_EQ(deformed.size(), std::size(all_methods));  // pictures of the paper's methods only
    for (const MethodResult& m : row.methods) {
        EXPECT_TRUE(m.ran) << m.label << ": " << m.status;
        EXPECT_EQ(m.quality.inverted, 0) << m.label;  // 30°: every method is valid (the paper's Table 1)
        EXPECT_EQ(m.quality.cells, static_cast<std::int64_t>(mesh.cells.size()));
    }
    EXPECT_EQ(row.methods[6].label, "dg-idw L=auto");
    // The paper's figures beside ours, in the Markdown and the JSON.
    const BenchInfo info{"a machine", "2026-11-29 22:00 UTC", "abc123", 1, false, 1.5};
    const std::string md = bench_markdown(info, {row});
    EXPECT_NE(md.find("## rect-box, rotate-30 — paper Tables 1-3"), std::string::npos);
    EXPECT_NE(md.find(" | 0.952 | "), std::string::npos);
    const nlohmann::json j = bench_json(info, {row});
    EXPECT_EQ(j.at("rows")[0].at("methods")[0].at("paper").at("min"), 0.784);
    EXPECT_TRUE(j.at("rows")[0].at("methods")[6].at("paper").at("min").is_null());  // a variant: no paper figures
    EXPECT_NE(bench_text(row).find("dg-idw continuous"), std::string::npos);
}
