#!/usr/bin/env python3
"""Live rate of the replayed graph: launch/replay.launch (tracking + fusion, headless) plays a
recording at RATE x its speed; counts the depth frames the player published and the frames the
fusion node processed (/fusion/status, one per tracked frame), and reports the dropped ones
and the node's per-frame time. Usage (workspace sourced):
    bench/graph/live_rate.py [BAG] [RATE]     # defaults: bags/short_test.bag 3
"""
import os
import subprocess
import sys
import time

import rospy
from sensor_msgs.msg import Image
from vicc_msgs.msg import TrackingStatus

WORKSPACE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    bag = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                          os.path.join(WORKSPACE, "bags/short_test.bag"))
    rate = float(sys.argv[2]) if len(sys.argv) > 2 else 3.0
    port = 11400 + os.getpid() % 500
    os.environ["ROS_MASTER_URI"] = f"http://localhost:{port}"
    launch = subprocess.Popen(
        ["roslaunch", "-p", str(port), os.path.join(WORKSPACE, "launch/replay.launch"),
         f"bag:={bag}", f"rate:={rate}", "rviz:=false", "exit_at_end:=true"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(3.0)  # the master
    rospy.init_node("live_rate_bench", anonymous=True)
    depth_stamps, statuses, unseen = set(), [], []
    status_sub = rospy.Subscriber("/fusion/status", TrackingStatus, statuses.append,
                                  queue_size=1000)

    def on_depth(image):
        # A frame published before this script's status subscription was connected would
        # count as dropped although only its status went unseen: counted apart.
        if status_sub.get_num_connections() > 0:
            depth_stamps.add(image.header.stamp)
        else:
            unseen.append(image.header.stamp)

    rospy.Subscriber("/pico_flexx/image_depth", Image, on_depth, queue_size=100)
    launch.wait()
    processed = {status.header.stamp for status in statuses}
    totals = sorted(status.total_ms for status in statuses)
    lost = sum(status.state == TrackingStatus.STATE_LOST for status in statuses)
    median = totals[len(totals) // 2] if totals else float("nan")
    worst = totals[-1] if totals else float("nan")
    ordered = sorted(depth_stamps)
    dropped_at = [i for i, stamp in enumerate(ordered) if stamp not in processed]
    dropped = len(dropped_at)
    print(f"{os.path.basename(bag)} at {rate:g}x: {len(depth_stamps)} depth frames published, "
          f"{len(processed)} processed, {dropped} dropped, {lost} lost; tracker total "
          f"median {median:.1f} ms, max {worst:.1f} ms per frame "
          f"(budget at this rate: {1000.0 / (15.0 * rate):.1f} ms)")
    if dropped_at:
        print(f"  dropped frames (index in the recording): {dropped_at}")
    if unseen:
        print(f"  {len(unseen)} frame(s) at the start not counted: published before the status "
              f"subscription of this script was connected")
    return 0 if launch.returncode == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
