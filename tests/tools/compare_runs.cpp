// compare_runs A B: exit 0 when the results in directories A and B agree bit
// for bit (run_comparison.hpp), else 1 with the differences listed.
#include <iostream>

#include "app/run_comparison.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: compare_runs DIR_A DIR_B\n";
    return 2;
  }
  try {
    const auto differences = shockgas::app::testing::result_differences(argv[1], argv[2]);
    for (const auto& d : differences) std::cerr << d << "\n";
    std::cout << (differences.empty() ? "the results agree bit for bit\n" : "the results differ\n");
    return differences.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "compare_runs: " << e.what() << "\n";
    return 2;
  }
}
