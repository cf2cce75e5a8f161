/// Redraws the picture of every regression case: for each *.case under the given directories (or
/// each file given), writes the .svg beside it from the case's values.
///
///   collide_draw_cases DIR|FILE...     exit 1 if a case cannot be read or its picture written

#include "collide/laws/case_file.hpp"

#include <filesystem>
#include <iostream>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path arg = argv[i];
    if (fs::is_directory(arg)) {
      for (const auto& e : fs::directory_iterator(arg))
        if (e.path().extension() == ".case") files.push_back(e.path());
    } else {
      files.push_back(arg);
    }
  }
  int failed = 0;
  for (const fs::path& f : files) {
    try {
      fs::path svg = f;
      svg.replace_extension(".svg");
      collide::laws::write_svg(svg, collide::laws::read_case(f));
    } catch (const std::exception& e) {
      ++failed;
      std::cerr << f.string() << ": " << e.what() << '\n';
    }
  }
  std::cout << files.size() << " pictures drawn, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}
