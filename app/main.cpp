#include "shockgas/app/command.hpp"

int main(int argc, char** argv) { return shockgas::app::run_command(argc, argv); }
