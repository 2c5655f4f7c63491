/* The library tests/platform_test.cpp loads through platform/shared_library.hpp, on Linux and
 * under Wine: a data symbol to read and change (each private copy has its own). */
int platform_test_value = 42;

int platform_test_add(int a, int b) {
  return a + b;
}
