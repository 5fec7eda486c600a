// What an import makes of param 802 and the IO page's wiring (core/backup/BackupWiring): our
// magazine devices where they model the type, IO links where a sensor follows an actuator no device
// drives, and plain words for the rest. Each generated [magazine] must load as machine.toml does.
#include "core/backup/BackupWiring.h"
#include "core/config/MachineConfig.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace m350::config {
namespace {

using ::testing::HasSubstr;

params::ParameterTable machine(std::initializer_list<std::pair<int, double>> values) {
    params::ParameterTable p;
    for (auto [n, v] : values) {
        p.set(n, v);
    }
    return p;
}

// The [magazine] and [[io_links]] tables as the machine folder loader reads them.
MachineConfig loaded(const backup::ImportedWiring& wiring) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(::testing::TempDir()) /
                            ("backup-wiring-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(folder);
    std::ofstream(folder / "machine.toml", std::ios::trunc) << "dialect = \"m350\"\n"
                                                            << wiring.magazineToml << wiring.linksToml;
    auto config = loadMachineFolder(folder.string());
    fs::remove_all(folder);
    if (auto* error = std::get_if<ConfigError>(&config)) {
        ADD_FAILURE() << error->message;
        return {};
    }
    return std::get<MachineConfig>(config);
}

bool hasLink(const MachineConfig& m, int output, int input, double seconds, bool inverted) {
    return std::any_of(m.ioLinks.begin(), m.ioLinks.end(), [&](const machine::IoLink& l) {
        return l.output == output && l.input == input && l.delay == seconds && l.inverted == inverted;
    });
}

std::string unsupported(const backup::ImportedWiring& wiring) {
    std::string all;
    for (const Message& said : wiring.unsupported) {
        const std::string line = said.english();
        all += line + "\n";
    }
    return all;
}

TEST(BackupWiring, TypeThreeIsARackLoadedFromAboveAsTheFactoryFlowDoesIt) {
    backup::ImportedWiring w = backup::importWiring(
        machine({{801, 3}, {802, 3}, {830, 100}, {850, 400}, {870, -80}, {831, 160}, {851, 400}, {871, -80},
                 {832, 220}, {852, 400}, {872, -80}}));
    MagazineConfig m = loaded(w).magazine;
    EXPECT_EQ(m.device, MagazineConfig::Device::LinearRack);
    EXPECT_TRUE(m.topLoading);
    EXPECT_FALSE(m.onGantry);
    EXPECT_THAT(w.magazine.english(), HasSubstr("fixed row, 固定直排"));
    EXPECT_THAT(w.magazine.english(), HasSubstr("3 pockets"));
    EXPECT_TRUE(std::any_of(w.review.begin(), w.review.end(), [](const backup::ReviewItem& r) { return r.key == "magazine.loading"; }));
}

TEST(BackupWiring, TypeTwoIsARackOnTheGantryWhoseSlideSensorsFollowItsOutput) {
    backup::ImportedWiring w = backup::importWiring(machine({{801, 2}, {802, 2}, {830, 50}, {870, -60}, {831, 110}, {871, -60},
                                             {545, 1}, {546, 1}, {548, 2}, {549, 1}, {551, 3}, {552, 1},
                                             {753, 2}, {754, 1}, {755, 1},    // slide output OUT02, active 1
                                             {629, 5}, {630, 1}, {631, 1},    // magazine out on IN05, active 1
                                             {697, 6}, {698, 1}, {699, 0}})); // magazine in on IN06, active 0
    MagazineConfig m = loaded(w).magazine;
    EXPECT_TRUE(m.onGantry);
    EXPECT_TRUE(hasLink(loaded(w), 2, 5, 0.6, false));
    // "in" is active (0) while the slide is not out (0): the same level, so not inverted
    EXPECT_TRUE(hasLink(loaded(w), 2, 6, 0.6, false));
    EXPECT_TRUE(w.unsupported.empty()) << unsupported(w);
}

TEST(BackupWiring, TypeOneIsTheMultiHeadDeviceUpToFourHeads) {
    EXPECT_EQ(loaded(backup::importWiring(machine({{801, 4}, {802, 1}}))).magazine.device, MagazineConfig::Device::MultiHead);
    backup::ImportedWiring six = backup::importWiring(machine({{801, 6}, {802, 1}}));
    EXPECT_TRUE(six.magazineToml.empty());
    EXPECT_THAT(unsupported(six), HasSubstr("with 6 heads: the simulator models at most 4"));
}

TEST(BackupWiring, AServoDiscAnUnknownTypeAndARackWithoutPositionsGetNoDeviceAndSaySo) {
    backup::ImportedWiring disc = backup::importWiring(machine({{801, 10}, {802, 4}}));
    EXPECT_TRUE(disc.magazineToml.empty());
    EXPECT_THAT(unsupported(disc), HasSubstr("servo disc, 圆盘刀库) is not modelled"));
    backup::ImportedWiring unknown = backup::importWiring(machine({{801, 10}, {802, 2.5}}));
    EXPECT_TRUE(unknown.magazineToml.empty());
    EXPECT_THAT(unsupported(unknown), HasSubstr("param 802 = 2.5 is no M350 magazine type"));
    backup::ImportedWiring bare = backup::importWiring(machine({{801, 8}, {802, 3}}));
    EXPECT_TRUE(bare.magazineToml.empty());
    EXPECT_THAT(unsupported(bare), HasSubstr("pocket 1 has no position"));
}

TEST(BackupWiring, ARackWithMorePocketsThanPositionsSaysWhichToolsHaveNone) {
    backup::ImportedWiring w = backup::importWiring(machine({{801, 20}, {802, 3}, {830, 100}, {831, 160}}));
    EXPECT_THAT(unsupported(w), HasSubstr("positions for 2 of its 20 pockets"));
    EXPECT_THAT(unsupported(w), HasSubstr("tools 3-20 have no pocket"));
}

TEST(BackupWiring, WithoutADeviceTheClampSensorsFollowTheDrawbarAtParam814) {
    backup::ImportedWiring w = backup::importWiring(machine({{802, 0}, {750, 1}, {751, 1}, {752, 1}, {814, 300},
                                             {623, 11}, {624, 1}, {625, 1},    // released: active 1
                                             {626, 12}, {627, 1}, {628, 1}})); // clamped: active 1
    EXPECT_TRUE(hasLink(loaded(w), 1, 11, 0.3, false));
    EXPECT_TRUE(hasLink(loaded(w), 1, 12, 0.3, true));
    // with a device the rack moves the cylinder and drives those sensors itself
    backup::ImportedWiring rack = backup::importWiring(machine({{801, 1}, {802, 3}, {830, 100}, {750, 1}, {751, 1}, {752, 1},
                                                {623, 11}, {624, 1}, {625, 1}}));
    EXPECT_TRUE(rack.linksToml.empty()) << rack.linksToml;
    EXPECT_TRUE(rack.unsupported.size() == 3u) << unsupported(rack); // only the three missing home switches
}

TEST(BackupWiring, SensorsNothingDrivesAndAlarmInputsAreNamed) {
    backup::ImportedWiring w = backup::importWiring(machine({{545, 1}, {546, 1}, {548, 2}, {549, 1}, {551, 3}, {552, 1},
                                             {632, 9}, {633, 1},          // dust cover sensor, no output
                                             {500, 20}, {501, 1},         // X servo alarm
                                             {638, 21}, {639, 1}}));      // custom alarm 1
    const std::string text = unsupported(w);
    EXPECT_THAT(text, HasSubstr("IN09 (dust cover, param 632) is wired but nothing in the simulation moves it"));
    EXPECT_THAT(text, HasSubstr("X servo alarm IN20, custom alarm 1 IN21"));
    EXPECT_THAT(text, ::testing::Not(HasSubstr("no home switch")));
    backup::ImportedWiring none = backup::importWiring(machine({}));
    EXPECT_THAT(unsupported(none), HasSubstr("no home switch is wired for Z (param 551)"));
}

} // namespace
} // namespace m350::config
