#include "linemap/map_io.h"
#include "print_size.h"

// Loads a ROS map with the full library and prints its size.
int main(int argc, char** argv) {
  return PrintSize(argc, argv, [](const char* path) { return linemap::LoadRosMap(path); });
}
