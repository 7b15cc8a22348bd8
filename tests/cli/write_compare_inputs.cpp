// Writes the tiny inputs of the `femto compare` CLI tests into the folder
// given as argument (run as a ctest fixture before them):
//   ref.exr, test.exr  4x3 RGB, 0.5 everywhere; test has +1 in channel 0 of pixel (1, 1)
//   small.exr          2x2 RGB
//   ref.npy, test.npy  4x3 volumes, 8 bins (OPL 1 + 0.5 i), sidecars; test has +1 in bin 2
//   bins4.npy          4 bins;  shifted.npy: the window starts at OPL 2;  bare.npy: no sidecar
#include <iostream>

#include "../unit/compare_test_files.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: femto_write_compare_inputs DIR\n";
    return 2;
  }
  namespace t = femto::test;
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  auto flat = [](int, int, int) { return 0.5f; };
  t::writeTestImage(dir / "ref.exr", 4, 3, 3, flat);
  t::writeTestImage(dir / "test.exr", 4, 3, 3, [](int x, int y, int c) { return x == 1 && y == 1 && c == 0 ? 1.5f : 0.5f; });
  t::writeTestImage(dir / "small.exr", 2, 2, 3, flat);
  auto one = [](int, int, int, int) { return 1.0f; };
  t::writeTestVolume(dir / "ref.npy", 4, 3, 8, one, t::testGrid(8));
  t::writeTestVolume(dir / "test.npy", 4, 3, 8, [](int, int, int b, int) { return b == 2 ? 2.0f : 1.0f; }, t::testGrid(8));
  t::writeTestVolume(dir / "bins4.npy", 4, 3, 4, one, t::testGrid(4));
  t::writeTestVolume(dir / "shifted.npy", 4, 3, 8, one, t::testGrid(8, 2.0));
  t::writeTestVolume(dir / "bare.npy", 4, 3, 8, one);
  return 0;
}
