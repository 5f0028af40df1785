#include "linemap/codec.h"
#include "print_size.h"

// Loads an .lmap file with the decoder library alone and prints its size.
int main(int argc, char** argv) {
  return PrintSize(argc, argv, [](const char* path) { return linemap::LoadLmap(path); });
}
