#include "apcs/cli/command_line.h"

#include <iostream>

int main(int argc, char** argv)
{
    return apcs::run_command_line(argc, argv, std::cout, std::cerr);
}
