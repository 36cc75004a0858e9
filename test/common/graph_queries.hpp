#pragma once
// Shared by the rostests that watch a launched graph: which nodes the master knows and who
// subscribes to a topic.

#include <algorithm>
#include <string>
#include <vector>

#include <XmlRpcValue.h>
#include <ros/ros.h>

namespace vicc_test {

inline bool nodeIsRegistered(const std::string& name) {
  std::vector<std::string> nodes;
  if (!ros::master::getNodes(nodes)) return false;
  return std::find(nodes.begin(), nodes.end(), name) != nodes.end();
}

/// True if the master lists `node` among the subscribers of `topic`.
inline bool nodeSubscribes(const std::string& node, const std::string& topic) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", request, response, payload, false)) return false;
  XmlRpc::XmlRpcValue& subscriptions = payload[1];
  for (int i = 0; i < subscriptions.size(); ++i) {
    if (static_cast<std::string>(subscriptions[i][0]) != topic) continue;
    XmlRpc::XmlRpcValue& subscribers = subscriptions[i][1];
    for (int j = 0; j < subscribers.size(); ++j)
      if (static_cast<std::string>(subscribers[j]) == node) return true;
  }
  return false;
}

}  // namespace vicc_test
