// The maps of ../shared/maps that parameters are tuned on, and the ones held
// out to judge them (tools/bench_tiles, tools/bench_tolerance): a choice
// that only helps the tuning maps shows as a gap between the two groups.
#ifndef LINEMAP_TOOLS_BENCH_TUNING_SPLIT_H_
#define LINEMAP_TOOLS_BENCH_TUNING_SPLIT_H_

namespace linemap::bench {

struct SplitMap {
  const char* path;  // relative to the maps folder (the YAML where there is one)
  bool tuning;
};

inline constexpr SplitMap kTuningSplit[] = {
    {"aws_bookstore/map.yaml", true},
    {"aws_warehouse/002/map.yaml", true},
    {"f1tenth/columbia.yaml", true},
    {"f1tenth/levinelobby.yaml", true},
    {"fetch/3_1_16_localization.yaml", true},
    {"fetch/4_26_15.yaml", true},
    {"mrpt/map1.png", true},
    {"nav2/depot.yaml", true},
    {"nav2/map.pgm", true},
    {"nav2/tb3_sandbox.yaml", true},
    {"navtut/lse_arena.yaml", true},
    {"rosnav1/willow-full-0.05.pgm", true},
    {"strands/bham/cs_lg.yaml", true},
    {"strands/tsc/tsc.yaml", true},
    {"turtlebot_apps/willow-2010-02-18-0.10.yaml", true},
    {"uos/avz.yaml", true},
    {"f1tenth/mtl.yaml", false},
    {"fetch/9_16_15.yaml", false},
    {"nav2/warehouse.yaml", false},
    {"strands/kth/map.yaml", false},
    {"uos/avz5floor_plan.yaml", false},
    {"turtlebot_apps/ctrl_room.yaml", false},
    {"aws_warehouse/005/map.yaml", false},
    {"stage_ros/willow-full.pgm", false},
    {"nav2/empty_room.pgm", false},
};

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_TUNING_SPLIT_H_
