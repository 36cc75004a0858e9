#pragma once
// Service calls that survive roscpp's lost responses. With a non-persistent connection the
// server closes the socket right after writing its response, and roscpp 1.15 (Debian's) can
// see that hang-up (POLLRDHUP) before it has read the response: the call then returns false
// although the server answered (ros/ros_comm#1976; seen once in ~1800 tests under load). A
// request that may be sent twice without harm (a query, a selection, a render) is therefore
// retried; one that must not (recording an examination) is not, and its caller sees false.

#include <ros/service.h>
#include <ros/service_client.h>

#include <string>

namespace vicc_common {

/// Calls until the transport succeeds, at most `attempts` times; whether it did. Only for
/// requests that may be repeated: a response lost after the server acted would act twice.
template <class Service>
bool callRepeatableService(const std::string& name, Service& service, int attempts = 3) {
  for (int attempt = 0; attempt < attempts; ++attempt) {
    if (ros::service::call(name, service)) return true;
  }
  return false;
}

/// The same through a ServiceClient.
template <class Service>
bool callRepeatableService(ros::ServiceClient& client, Service& service, int attempts = 3) {
  for (int attempt = 0; attempt < attempts; ++attempt) {
    if (client.call(service)) return true;
  }
  return false;
}

}  // namespace vicc_common
