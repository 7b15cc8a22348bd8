// femto command-line interface (placeholder until the CLI lands).
#include <iostream>

int main() {
  std::cout << "femto 0.1.0\n";
  return 0;
}
