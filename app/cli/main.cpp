#include <iostream>

#include "spira/base/version.h"

int main(int argc, char** argv)
{
  std::cout << "spira-cli " << spira::kVersion << "\n";
  return 0;
}
