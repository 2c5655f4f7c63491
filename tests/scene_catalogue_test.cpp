// The scene library as a user finds it: every in-tree scene filed (family tag, credit,
// description), `list --tag/--search/--json` picking exactly what they say, the choice parameter
// (ABI 1.2) by name on the command line, in path files and in the kernel, and presets: applied
// exactly as the values they name, checked by `check --preset`, and every kind of broken preset
// file reported with its file and line.
#include "cli_run.hpp"
#include "in_tree_scenes.hpp"
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_checks.hpp"
#include "plugin/scene_instance.hpp"
#include "render/kernel_assembly.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <set>

namespace fr {
namespace {

using test::CliRun;
using test::expect_usage_error;
using test::run;

nlohmann::json list_json(const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"list", "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  const CliRun r = run(args);
  EXPECT_EQ(r.code, 0) << r.err << r.out;
  return nlohmann::json::parse(r.out);
}

std::set<std::string> ids_of(const nlohmann::json& doc) {
  std::set<std::string> ids;
  for (const auto& s : doc["scenes"]) ids.insert(s["id"].get<std::string>());
  return ids;
}

const std::set<std::string> kFamilies = {"bulb", "box",   "kifs",   "kleinian", "hypercomplex",
                                         "ifs",  "kali",  "hybrid", "showcase"};

// Every scene is filed under one of the families (its first tag), names who found its formula,
// and says in a sentence what it is; the families the issue names all have scenes.
TEST(SceneCatalogue, EverySceneIsFiledAndCredited) {
  const nlohmann::json doc = list_json();
  const auto ids = test::in_tree_scene_ids();
  ASSERT_EQ(doc["scenes"].size(), ids.size());
  ASSERT_GE(ids.size(), 40u);
  std::map<std::string, int> per_family;
  for (const auto& s : doc["scenes"]) {
    const std::string id = s["id"];
    ASSERT_FALSE(s["tags"].empty()) << id;
    const std::string family = s["family"];
    EXPECT_TRUE(kFamilies.count(family)) << id << " is filed under '" << family << "'";
    ++per_family[family];
    EXPECT_GE(s["credit"].get<std::string>().size(), 10u) << id;
    EXPECT_GE(s["description"].get<std::string>().size(), 20u) << id;
  }
  for (const std::string& family : kFamilies)
    EXPECT_GE(per_family[family], 1) << "no scene in family " << family;
}

// --tag keeps exactly the scenes with that tag; --search keeps those whose text holds every word
// (case-insensitive); both together keep the intersection; nothing found says so.
TEST(SceneCatalogue, ListFilters) {
  const nlohmann::json all = list_json();
  std::set<std::string> kifs, lowe;
  for (const auto& s : all["scenes"]) {
    for (const auto& t : s["tags"])
      if (t == "kifs") kifs.insert(s["id"].get<std::string>());
    if (s["credit"].get<std::string>().find("Tom Lowe") != std::string::npos)
      lowe.insert(s["id"].get<std::string>());
  }
  // The five polyhedra at least (the hybrid composer and the crystal garden are tagged too).
  for (const char* id : {"kifs_cube", "kifs_dodecahedron", "kifs_icosahedron", "kifs_octahedron",
                         "kifs_tetrahedron", "hybrid"})
    EXPECT_TRUE(kifs.count(id)) << id;
  EXPECT_FALSE(kifs.count("mandelbulb"));
  EXPECT_EQ(ids_of(list_json({"--tag", "kifs"})), kifs);
  EXPECT_EQ(ids_of(list_json({"--search", "tom LOWE"})), lowe);
  EXPECT_GE(lowe.size(), 4u);
  EXPECT_EQ(ids_of(list_json({"--search", "knighty pseudo"})),
            (std::set<std::string>{"pseudo_kleinian"}));
  EXPECT_EQ(ids_of(list_json({"--tag", "box", "--search", "4D"})),
            (std::set<std::string>{"mandelbox_4d"}));
  const CliRun none = run({"list", "--tag", "nosuchtag"});
  EXPECT_EQ(none.code, 0);
  EXPECT_NE(none.out.find("no scene matches --tag nosuchtag"), std::string::npos) << none.out;
}

// The hybrid's steps are choices: listed by name with their names, set by name, never by index.
TEST(SceneCatalogue, ChoiceParametersByName) {
  const nlohmann::json doc = list_json({"--search", "hybrid composer"});
  ASSERT_EQ(doc["scenes"].size(), 1u);
  const auto& params = doc["scenes"][0]["params"];
  const auto step1 = std::find_if(params.begin(), params.end(),
                                  [](const auto& p) { return p["key"] == "step1"; });
  ASSERT_NE(step1, params.end());
  EXPECT_EQ((*step1)["type"], "choice");
  EXPECT_EQ((*step1)["default"], "box_fold");
  EXPECT_EQ((*step1)["choices"].size(), 13u);
  EXPECT_EQ((*step1)["choices"][5], "menger");
  expect_usage_error({"render", "--scene", "hybrid", "--param", "step1=nonsense"},
                     "'nonsense' is not a value of 'step1' (one of: none, bulb, box_fold,");
  expect_usage_error({"render", "--scene", "hybrid", "--param", "step1=5"},
                     "'5' is not a value of 'step1'");
  const CliRun text = run({"list", "--search", "hybrid composer"});
  EXPECT_NE(text.out.find("--param step1=box_fold  choice of none|bulb|box_fold|"),
            std::string::npos)
      << text.out;
}

// In the kernel a choice is its index, with a name for each value; compiled in, the switch over
// the kinds keeps only the chosen one.
TEST(SceneCatalogue, ChoicesInTheKernel) {
  const LoadOutcome o = load_scene_plugin(std::filesystem::path(SCENE_PLUGIN_DIR) /
                                          ("hybrid" PLUGIN_SUFFIX));
  ASSERT_TRUE(o.scene) << o.message;
  const SceneInfo& info = o.scene->info;
  SceneState state = make_default_state(info);
  state.params[info.find_param("step1")].v[0] = 5;  // menger
  const AssembledKernel k = assemble_probe_kernel(info, state.params, KernelConfig{1, Precision::Float});
  EXPECT_NE(k.source.find("#define FR_CHOICE_step1_menger 5\n"), std::string::npos);
  EXPECT_NE(k.source.find("#define FR_CHOICE_estimate_box 2\n"), std::string::npos);
  EXPECT_NE(k.source.find("#define FR_PARAM_step1 (5)\n"), std::string::npos);
}

// The descriptor's rules for choices: names are identifiers, none twice, min 0 and max the last
// index, and only a choice has names.
TEST(SceneCatalogue, ChoiceRules) {
  const LoadOutcome o = load_scene_plugin(std::filesystem::path(SCENE_PLUGIN_DIR) /
                                          ("hybrid" PLUGIN_SUFFIX));
  ASSERT_TRUE(o.scene) << o.message;
  const SceneInfo good = o.scene->info;
  EXPECT_EQ(check_scene_info(good), std::nullopt);
  const size_t step = static_cast<size_t>(good.find_param("step1"));
  auto broken = [&](auto change, const std::string& says) {
    SceneInfo info = good;
    change(info.params[step]);
    const auto problem = check_scene_info(info);
    ASSERT_TRUE(problem.has_value()) << says;
    EXPECT_NE(problem->find(says), std::string::npos) << *problem;
  };
  broken([](ParamInfo& p) { p.choices[2] = "bulb"; }, "choice name 'bulb' appears twice");
  broken([](ParamInfo& p) { p.choices[0] = "Not-an-id"; }, "must match [a-z][a-z0-9_]*");
  broken([](ParamInfo& p) { p.max_value.v[0] = 20; }, "max its number of names minus 1 (12)");
  broken([](ParamInfo& p) { p.choices.clear(); }, "needs 1 to 64 names");
  broken(
      [](ParamInfo& p) {
        p.type = FR_PARAM_INT;
        p.max_value.v[0] = 12;
      },
      "only a choice has names");
}

// ABI 1.4's detail ratio: the Mandelbox's iteration count declares 2 (read from the plugin), and
// only an int count may have one, above 1 and finite.
TEST(SceneCatalogue, DetailRatioRules) {
  const LoadOutcome o = load_scene_plugin(std::filesystem::path(SCENE_PLUGIN_DIR) /
                                          ("mandelbox" PLUGIN_SUFFIX));
  ASSERT_TRUE(o.scene) << o.message;
  const SceneInfo good = o.scene->info;
  const int count = good.find_param("iterations");
  ASSERT_GE(count, 0);
  EXPECT_EQ(good.params[count].detail_ratio, 2.0);
  EXPECT_EQ(good.params[good.find_param("scale")].detail_ratio, 0.0);
  EXPECT_EQ(check_scene_info(good), std::nullopt);
  auto broken = [&](const std::string& key, double ratio, const std::string& says) {
    SceneInfo info = good;
    info.params[info.find_param(key)].detail_ratio = ratio;
    const auto problem = check_scene_info(info);
    ASSERT_TRUE(problem.has_value()) << key << " " << ratio;
    EXPECT_NE(problem->find(says), std::string::npos) << *problem;
  };
  broken("scale", 2, "only an int iteration count has a detail_ratio");
  for (double ratio : {0.5, 1.0, -2.0, double(NAN), double(INFINITY), 1e7})
    broken("iterations", ratio, "must be above 1 and finite");
}

const std::vector<std::string> kHybridPresets = {"bulb_in_a_box", "folded_cubic_bulb",
                                                 "icosahedral_twist", "spun_spiky_box",
                                                 "twisted_menger"};

// A preset is exactly the values and view it names: the same picture, byte for byte, as those
// given by hand; --param still overrides it.
TEST(SceneCatalogue, PresetIsItsValuesAndView) {
  const auto dir = test::fresh_dir("catalogue_preset");
  auto render = [&](std::vector<std::string> args, const std::string& name) {
    args.insert(args.begin(), "render");
    args.insert(args.end(), {"--size", "48x32", "--out", (dir / name).string()});
    const CliRun r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return test::read_file(dir / name);
  };
  const std::string preset = render({"--preset", "twisted_menger"}, "preset.png");
  const std::string by_hand =
      render({"--scene", "hybrid", "--param", "step1=menger", "--param", "step1_a=3", "--param",
              "step1_v=1,1,1", "--param", "step2=rotate", "--param", "step2_v=10,20,0", "--param",
              "step3=none", "--param", "step4=none", "--param", "iterations=6", "--param",
              "estimate=box", "--param", "bound=2", "--eye", "2.5,1.8,3", "--target", "0,0,0"},
             "hand.png");
  ASSERT_FALSE(preset.empty());
  EXPECT_EQ(preset, by_hand);
  EXPECT_NE(render({"--preset", "twisted_menger", "--param", "step2_v=0,0,0"}, "over.png"),
            preset);
  expect_usage_error({"render", "--preset", "twisted_menger", "--scene", "mandelbulb"},
                     "--preset twisted_menger is for scene 'hybrid', not --scene mandelbulb");
  expect_usage_error({"render", "--preset", "nope"}, "--preset: no preset 'nope' (there are: ");
}

// Each shipped hybrid preset passes every conformance check at its own values (its DE stays a
// lower bound, inside its own bounding radius).
TEST(SceneCatalogue, HybridPresetsPassCheck) {
  const auto file = std::filesystem::path(SCENE_PLUGIN_DIR) / ("hybrid" PLUGIN_SUFFIX);
  ASSERT_GE(kHybridPresets.size(), 5u);
  for (const std::string& preset : kHybridPresets) {
    const test::ProgramRun r = test::run_fractalis({"check", file.string(), "--preset", preset});
    EXPECT_EQ(r.exit_code, 0) << preset << "\n" << r.output;
    EXPECT_NE(r.output.find("at preset '" + preset + "'"), std::string::npos) << r.output;
  }
}

// A plugin folder with broken presets beside a good one: `list` reports each with its file (and
// line where there is one) and exits 1, the good preset still works, and --preset on a broken one
// is a usage error that says what is wrong.
TEST(SceneCatalogue, BrokenPresetsAreReportedNotUsed) {
  const auto dir = test::fresh_dir("catalogue_hostile");
  std::filesystem::copy_file(std::filesystem::path(SCENE_PLUGIN_DIR) / ("hybrid" PLUGIN_SUFFIX),
                             dir / ("hybrid" PLUGIN_SUFFIX));
  std::filesystem::create_directories(dir / "presets" / "folder.toml");
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / "presets" / name, std::ios::binary) << text;
  };
  write("good.toml", "scene = \"hybrid\"\nname = \"Good\"\n[params]\nstep1 = \"menger\"\n");
  write("typo.toml", "scene = \"hybrid\"\nname = \"Typo\"\ncolour = 1\n");
  write("unknown_param.toml", "scene = \"hybrid\"\nname = \"U\"\n[params]\npower = 8\n");
  write("bad_choice.toml", "scene = \"hybrid\"\nname = \"C\"\n[params]\nstep1 = \"warp\"\n");
  write("index_choice.toml", "scene = \"hybrid\"\nname = \"I\"\n[params]\nstep1 = 5\n");
  write("out_of_range.toml", "scene = \"hybrid\"\nname = \"R\"\n[params]\nstep1_a = 99\n");
  write("missing_scene.toml", "scene = \"no_such_scene\"\nname = \"M\"\n");
  write("no_name.toml", "scene = \"hybrid\"\n");
  write("not_toml.toml", "scene = \"hybrid\n");
  write("bad_camera.toml",
        "scene = \"hybrid\"\nname = \"B\"\n[camera]\neye = [0, 0, 0]\ntarget = [0, 0, 0]\n");
  write("Bad Name.toml", "scene = \"hybrid\"\nname = \"N\"\n");
  write("huge.toml", "scene = \"hybrid\"\nname = \"H\"\n# " + std::string(70000, 'x') + "\n");
  const CliRun r = run({"list", "--plugins", dir.string()});
  EXPECT_EQ(r.code, 1) << r.out;
  const std::string presets = (dir / "presets").string();
  for (const std::string& says :
       {presets + "/typo.toml:3: unknown key 'colour'",
        presets + "/unknown_param.toml:4: scene 'hybrid' has no parameter 'power'",
        presets + "/bad_choice.toml:4: step1: expected one of the names none, bulb,",
        presets + "/index_choice.toml:4: step1: expected one of the names",
        presets + "/out_of_range.toml:4: step1_a: outside the range of 'step1_a'",
        std::string("preset 'missing_scene' is for scene 'no_such_scene', which is not there"),
        presets + "/no_name.toml: needs name",
        presets + "/not_toml.toml:1: not valid TOML",
        presets + "/bad_camera.toml:3: camera: target equals eye",
        presets + "/Bad Name.toml: the file name must be the preset's id",
        presets + "/huge.toml: larger than 65536 bytes",
        presets + "/folder.toml: cannot be read"})
    EXPECT_NE(r.out.find(says), std::string::npos) << says << "\n" << r.out;
  EXPECT_NE(r.out.find("--preset good  Good"), std::string::npos) << r.out;
  const auto out = (dir / "good.png").string();
  const CliRun good = run({"render", "--plugins", dir.string(), "--preset", "good", "--size",
                           "16x16", "--out", out});
  EXPECT_EQ(good.code, 0) << good.err;
  expect_usage_error({"render", "--plugins", dir.string(), "--preset", "bad_choice"},
                     "bad_choice.toml:4: step1: expected one of the names");
  expect_usage_error({"render", "--plugins", dir.string(), "--preset", "typo"},
                     "typo.toml:3: unknown key 'colour'");
}


// The width and height a PNG file's header states (bytes 16 to 23, big-endian), or 0, 0.
std::pair<int, int> png_size(const std::string& bytes) {
  if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0) return {0, 0};
  auto be32 = [&](size_t at) {
    return (int(uint8_t(bytes[at])) << 24) | (int(uint8_t(bytes[at + 1])) << 16) |
           (int(uint8_t(bytes[at + 2])) << 8) | int(uint8_t(bytes[at + 3]));
  };
  return {be32(16), be32(20)};
}

// `gallery` on a folder of two scenes and one preset: a picture of each at the size asked for,
// an index.html that names each with its family, credit and command and links its picture, and
// a sheet with every picture in a grid; a --out that is a file is refused.
TEST(SceneCatalogue, GalleryWritesPicturesIndexAndSheet) {
  const auto dir = test::fresh_dir("catalogue_gallery");
  const auto plugins = dir / "plugins";
  std::filesystem::create_directories(plugins / "presets");
  for (const char* scene : {"menger", "sierpinski"})
    std::filesystem::copy_file(std::filesystem::path(SCENE_PLUGIN_DIR) / (scene + std::string(PLUGIN_SUFFIX)),
                               plugins / (scene + std::string(PLUGIN_SUFFIX)));
  std::ofstream(plugins / "presets" / "deep_sponge.toml")
      << "scene = \"menger\"\nname = \"Deep\"\ndescription = \"Five levels.\"\n[params]\n"
         "iterations = 5\n";
  const auto out = dir / "gallery";
  const auto sheet = dir / "sheet.png";
  const CliRun r = run({"gallery", "--plugins", plugins.string(), "--out", out.string(), "--size",
                        "40x24", "--sheet", sheet.string(), "--columns", "2"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("wrote 3 pictures"), std::string::npos) << r.out;
  for (const char* file : {"menger.png", "menger--deep_sponge.png", "sierpinski.png"})
    EXPECT_EQ(png_size(test::read_file(out / file)), std::make_pair(40, 24)) << file;
  // Two columns of 40 + 4 and two rows of 24 + 4, and the outer 4-pixel margin.
  EXPECT_EQ(png_size(test::read_file(sheet)), std::make_pair(2 * 44 + 4, 2 * 28 + 4));
  const std::string index = test::read_file(out / "index.html");
  for (const char* part :
       {"<img src=\"menger.png\"", "<img src=\"menger--deep_sponge.png\"", "<img src=\"sierpinski.png\"",
        "--preset deep_sponge", "--scene sierpinski", "Menger sponge: Deep", "Five levels.",
        "Karl Menger", "<small>ifs</small>"})
    EXPECT_NE(index.find(part), std::string::npos) << part << "\n" << index;
  std::ofstream(dir / "a_file") << "x";
  expect_usage_error({"gallery", "--plugins", plugins.string(), "--out", (dir / "a_file").string()},
                     "cannot make that folder");
}
}  // namespace
}  // namespace fr
