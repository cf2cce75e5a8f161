// collide_describe: what the build knows about kinds and laws, as JSON for the scripts, so that
// none of them keeps its own list or parses a header.
//
//   collide_describe            {"kinds": [...], "transform": {...}, "laws": [...]}
//   collide_describe --kinds    the kinds with their codecs only
//   collide_describe --laws     the law table only
//
// A kind: name, index (its kind byte), layout (fixed, vertices, children), fields (name, role),
// sample values, byte_prefix. A law: name, inputs (pair, shape, values, scene, transform_values,
// chain), suite (static, placed, moving, chain), description.

#include "collide/laws/codec.hpp"
#include "collide/laws/laws.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <string>

namespace {

using nlohmann::json;
using namespace collide;

json fields_json(std::span<const laws::Field> fields) {
  json out = json::array();
  for (const laws::Field& f : fields) out.push_back({{"name", f.name}, {"role", laws::name(f.role)}});
  return out;
}

json kinds_json() {
  json out = json::array();
  for (const ShapeKind k : kKinds) {
    const laws::KindCodec c = laws::codec_of(k);
    out.push_back({{"name", name(k)},
                   {"index", static_cast<int>(k)},
                   {"layout", laws::name(c.layout)},
                   {"fields", fields_json(c.fields)},
                   {"sample", std::vector<double>(c.sample.begin(), c.sample.end())},
                   {"byte_prefix", std::vector<int>(c.byte_prefix.begin(), c.byte_prefix.end())}});
  }
  return out;
}

json laws_json() {
  json out = json::array();
  for (const laws::LawInfo& row : laws::kLaws) {
    out.push_back({{"name", row.name},
                   {"inputs", laws::name(row.inputs)},
                   {"suite", laws::name(row.suite)},
                   {"description", row.description}});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The kinds with their codecs and the law table of this build, as JSON"};
  bool kinds = false, laws = false;
  app.add_flag("--kinds", kinds, "only the kinds and their codecs");
  app.add_flag("--laws", laws, "only the law table");
  CLI11_PARSE(app, argc, argv);
  json out;
  if (kinds) {
    out = kinds_json();
  } else if (laws) {
    out = laws_json();
  } else {
    out = {{"kinds", kinds_json()},
           {"transform",
            {{"fields", fields_json(laws::TransformCodec::fields)},
             {"identity",
              std::vector<double>(laws::TransformCodec::identity.begin(), laws::TransformCodec::identity.end())}}},
           {"laws", laws_json()}};
  }
  std::cout << out.dump(1) << '\n';
  return 0;
}
