// The encoder's layout of LAYR (spec/format.md 9).
#include "codec/layers/section_order.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <utility>

#include "codec/layers/layer_order.h"
#include "codec/layers/layer_sections.h"

namespace linemap {
namespace {

const std::vector<CellIndex>& PointsOf(const WallPolyline& wall) { return wall.points; }
const std::vector<CellIndex>& PointsOf(const RoomOutline& room) { return room.polygon; }
const std::vector<CellIndex>& PointsOf(const FurnitureObject& object) { return object.polygon; }

// Stable grouping by section; returns each item's section in the new order.
template <class Item>
std::vector<std::int64_t> GroupBySection(int width, int side, std::vector<Item>* items) {
  std::vector<std::pair<std::int64_t, std::size_t>> keys;
  keys.reserve(items->size());
  for (std::size_t i = 0; i < items->size(); ++i)
    keys.emplace_back(SectionOfPoints(PointsOf((*items)[i]), width, side), i);
  std::stable_sort(keys.begin(), keys.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Item> grouped;
  grouped.reserve(items->size());
  std::vector<std::int64_t> sections;
  sections.reserve(items->size());
  for (const auto& [section, i] : keys) {
    grouped.push_back(std::move((*items)[i]));
    sections.push_back(section);
  }
  *items = std::move(grouped);
  return sections;
}

// Each section's run of a grouped list ordered for coding on its own (a
// tour per section).
template <class Item, class Order>
void OrderRuns(const std::vector<std::int64_t>& sections, std::vector<Item>* items, Order order) {
  for (std::size_t begin = 0; begin < items->size();) {
    std::size_t end = begin + 1;
    while (end < items->size() && sections[end] == sections[begin]) ++end;
    if (end - begin >= 2) {
      std::vector<Item> run(std::make_move_iterator(items->begin() + begin),
                            std::make_move_iterator(items->begin() + end));
      order(&run);
      std::move(run.begin(), run.end(), items->begin() + begin);
    }
    begin = end;
  }
}

// Room ids 1, 2, ... in list order when `always` or when they do not
// increase already; the objects' room ids follow (-1 for an id no room
// has).
void RenumberRooms(bool always, std::vector<RoomOutline>* rooms,
                   std::vector<FurnitureObject>* furniture) {
  bool increasing = !always;
  for (std::size_t i = 1; i < rooms->size() && increasing; ++i) {
    increasing = (*rooms)[i].id > (*rooms)[i - 1].id;
  }
  if (increasing) return;
  std::map<std::uint32_t, std::uint32_t> new_id;
  for (std::size_t i = 0; i < rooms->size(); ++i) {
    new_id[(*rooms)[i].id] = static_cast<std::uint32_t>(i + 1);
    (*rooms)[i].id = static_cast<std::uint32_t>(i + 1);
  }
  for (FurnitureObject& object : *furniture) {
    if (object.room_id < 0) continue;
    const auto it = new_id.find(static_cast<std::uint32_t>(object.room_id));
    object.room_id = it == new_id.end() ? -1 : static_cast<std::int32_t>(it->second);
  }
}

}  // namespace

int LayerSectionSide(int width, int height, int requested) {
  if (requested > 0) return requested;
  const int side = std::max(width, height);
  if (side <= kOneSectionCells) return std::max(side, static_cast<int>(kMinSectionSide));
  return kSectionCells;
}

void OrderItemsInSections(int width, int height, int side, std::vector<WallPolyline>* walls,
                          std::vector<RoomOutline>* rooms,
                          std::vector<FurnitureObject>* furniture) {
  const std::vector<std::int64_t> wall_sections = GroupBySection(width, side, walls);
  GroupBySection(width, side, rooms);
  const std::vector<std::int64_t> object_sections = GroupBySection(width, side, furniture);
  if (width > side || height > side) {
    // One section is the whole map, already in the tour order of the
    // extraction; with more, each section's items get a tour of their own.
    OrderRuns(wall_sections, walls, OrderWallsForCoding);
    OrderRuns(object_sections, furniture, OrderFurnitureForCoding);
  }
}

void NumberItemsInOrder(bool renumber_rooms, std::vector<RoomOutline>* rooms,
                        std::vector<FurnitureObject>* furniture) {
  RenumberRooms(renumber_rooms, rooms, furniture);
  for (std::size_t i = 0; i < furniture->size(); ++i) {
    (*furniture)[i].id = static_cast<std::uint32_t>(i);
  }
}

void ArrangeLayersInSections(int width, int height, int side, std::vector<WallPolyline>* walls,
                             std::vector<RoomOutline>* rooms,
                             std::vector<FurnitureObject>* furniture) {
  OrderItemsInSections(width, height, side, walls, rooms, furniture);
  NumberItemsInOrder(false, rooms, furniture);
}

}  // namespace linemap
