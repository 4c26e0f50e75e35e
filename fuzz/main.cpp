// The scenfuzz executable: everything happens in run_cli (fuzz/cli.cpp).
#include "fuzz/cli.hpp"

int main(int argc, char** argv) { return scenfuzz::run_cli(argc, argv); }
