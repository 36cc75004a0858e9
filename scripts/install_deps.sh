#!/usr/bin/env bash
# Installs the Debian packages VICC needs. Idempotent: only missing packages
# are installed, and nothing is done (not even apt-get update) when all are there.
set -euo pipefail

PACKAGES=(
  # build tooling and ROS 1 from Debian
  build-essential cmake catkin python3-catkin-pkg python3-empy
  ros-base-dev libroscpp-dev librosbag-dev python3-rosbag ros-robot-dev rosbash
  python3-rostest python3-roslaunch python3-rostopic python3-rosnode ros-core-dev
  ros-message-generation ros-message-runtime
  ros-std-msgs ros-geometry-msgs ros-sensor-msgs ros-nav-msgs ros-visualization-msgs ros-std-srvs
  libtf2-ros-dev libtf2-eigen-dev libtf2-geometry-msgs-dev python3-tf2-ros
  libnodelet-dev libnodeletlib-dev pluginlib-dev libimage-transport-dev libmessage-filters-dev libcv-bridge-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  librviz-dev rviz
  # numerics, vision, geometry
  libeigen3-dev libopencv-dev libopencv-contrib-dev libpcl-dev libpcl-conversions-dev libceres-dev
  # data and formats
  libsqlite3-dev libyaml-cpp-dev nlohmann-json3-dev libtinyxml2-dev libassimp-dev assimp-testmodels
  python3-yaml
  libpotrace-dev libpng-dev
  # tests
  libgtest-dev googletest xvfb xauth imagemagick clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install_deps: done"
