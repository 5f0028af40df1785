// The nav_msgs types the nodes and the bag reader use, usable from C++20.
//
// Debian's generated ROS 1 messages name their containers through
// std::allocator<void>::rebind, which C++20 removed; nav_msgs::OccupancyGrid
// (OccupancyGrid_<std::allocator<void>>) therefore does not compile in
// linemap's C++20. The message templates themselves are fine with any
// allocator that has rebind, so the types here instantiate them with
// RosAllocator: same fields, same serialisation, same MD5 sums and type
// names (the traits are templates over the allocator), so they interoperate
// with every other ROS node. Only nav_msgs/GetMap.h cannot be included (its
// service struct instantiates the std::allocator<void> messages), so the
// service type and its traits are declared here, with the MD5 sum that file
// gives.
#ifndef LINEMAP_ROS_ROS_MESSAGES_H_
#define LINEMAP_ROS_ROS_MESSAGES_H_

#include <nav_msgs/GetMapRequest.h>
#include <nav_msgs/GetMapResponse.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/service_traits.h>

#include <memory>
#include <string>
#include <vector>

namespace linemap::ros_bridge {

// std::allocator with the member template rebind that C++20 dropped.
template <class T>
struct RosAllocator : std::allocator<T> {
  RosAllocator() = default;
  template <class U>
  RosAllocator(const RosAllocator<U>& /*other*/) {}  // NOLINT(runtime/explicit)
  template <class U>
  struct rebind {
    using other = RosAllocator<U>;
  };
};

using OccupancyGridMsg = nav_msgs::OccupancyGrid_<RosAllocator<void>>;
using MapMetaDataMsg = nav_msgs::MapMetaData_<RosAllocator<void>>;
using GetMapRequestMsg = nav_msgs::GetMapRequest_<RosAllocator<void>>;
using GetMapResponseMsg = nav_msgs::GetMapResponse_<RosAllocator<void>>;
// A message string / int8 array (their allocator is RosAllocator).
using MsgString = OccupancyGridMsg::_header_type::_frame_id_type;
using MsgInt8Array = OccupancyGridMsg::_data_type;

// nav_msgs/GetMap, as nav_msgs/GetMap.h declares it.
struct GetMapSrv {
  using Request = GetMapRequestMsg;
  using Response = GetMapResponseMsg;
  using RequestType = Request;
  using ResponseType = Response;
  Request request;
  Response response;
};

}  // namespace linemap::ros_bridge

namespace ros::service_traits {

// The values of nav_msgs/GetMap.h (rosmsg md5 nav_msgs/GetMap).
template <>
struct MD5Sum<linemap::ros_bridge::GetMapSrv> {
  static const char* value() { return "6cdd0a18e0aff5b0a3ca2326a89b54ff"; }
  static const char* value(const linemap::ros_bridge::GetMapSrv&) { return value(); }
};
template <>
struct DataType<linemap::ros_bridge::GetMapSrv> {
  static const char* value() { return "nav_msgs/GetMap"; }
  static const char* value(const linemap::ros_bridge::GetMapSrv&) { return value(); }
};
// A service's request and response carry the service's MD5 sum and type.
template <>
struct MD5Sum<linemap::ros_bridge::GetMapRequestMsg> {
  static const char* value() { return MD5Sum<linemap::ros_bridge::GetMapSrv>::value(); }
  static const char* value(const linemap::ros_bridge::GetMapRequestMsg&) { return value(); }
};
template <>
struct DataType<linemap::ros_bridge::GetMapRequestMsg> {
  static const char* value() { return DataType<linemap::ros_bridge::GetMapSrv>::value(); }
  static const char* value(const linemap::ros_bridge::GetMapRequestMsg&) { return value(); }
};
template <>
struct MD5Sum<linemap::ros_bridge::GetMapResponseMsg> {
  static const char* value() { return MD5Sum<linemap::ros_bridge::GetMapSrv>::value(); }
  static const char* value(const linemap::ros_bridge::GetMapResponseMsg&) { return value(); }
};
template <>
struct DataType<linemap::ros_bridge::GetMapResponseMsg> {
  static const char* value() { return DataType<linemap::ros_bridge::GetMapSrv>::value(); }
  static const char* value(const linemap::ros_bridge::GetMapResponseMsg&) { return value(); }
};

}  // namespace ros::service_traits

#endif  // LINEMAP_ROS_ROS_MESSAGES_H_
