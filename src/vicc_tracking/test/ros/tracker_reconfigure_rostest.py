#!/usr/bin/python3
"""dynamic_reconfigure of the running tracker (tracker_reconfigure.test): a valid ICP change is
applied to the frames that follow (min_inliers beyond any frame's pixel count makes ICP fail,
restoring it lets tracking recover), an invalid one is refused with the old value kept, and the
EKF noise is read back from the server and the parameter server."""
import math
import threading
import time
import unittest

import dynamic_reconfigure.client
import rospy
import rostest
from vicc_msgs.msg import TrackingStatus

TIMEOUT = 90.0  # wall seconds per step: a loaded machine, a looping bag with a still phase


class TrackerReconfigureTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("tracker_reconfigure_test")
        cls.lock = threading.Lock()
        cls.statuses = []
        rospy.Subscriber("/tracker/status", TrackingStatus, cls.on_status, queue_size=100)
        cls.icp = dynamic_reconfigure.client.Client("/tracker/icp", timeout=TIMEOUT)
        cls.ekf = dynamic_reconfigure.client.Client("/tracker/ekf", timeout=TIMEOUT)

    @classmethod
    def on_status(cls, status):
        with cls.lock:
            cls.statuses.append(status)

    def wait_for_status(self, predicate, what):
        """The first status after this call that satisfies predicate."""
        with self.lock:
            seen = len(self.statuses)
        deadline = time.time() + TIMEOUT
        while time.time() < deadline:
            with self.lock:
                fresh = self.statuses[seen:]
                seen = len(self.statuses)
            for status in fresh:
                if predicate(status):
                    return status
            time.sleep(0.05)
        self.fail("no status with %s within %.0f s" % (what, TIMEOUT))

    def test_icp_change_applies_and_invalid_is_refused(self):
        initial = self.icp.get_configuration(timeout=TIMEOUT)
        self.assertEqual(initial["min_inliers"], 200)  # IcpConfig's default, not the .cfg's
        self.assertAlmostEqual(initial["max_correspondence_distance"], 0.05)
        self.wait_for_status(lambda s: s.state == TrackingStatus.STATE_OK, "tracking")

        refused = self.icp.update_configuration({"min_inliers": 3})  # validate(): >= 6
        self.assertEqual(refused["min_inliers"], 200)
        self.assertEqual(rospy.get_param("/tracker/icp/min_inliers"), 200)
        refused = self.icp.update_configuration({"max_normal_angle_deg": 120.0})  # (0, 90]
        self.assertAlmostEqual(refused["max_normal_angle_deg"], 30.0)
        self.wait_for_status(lambda s: s.state == TrackingStatus.STATE_OK, "tracking still")

        applied = self.icp.update_configuration({"min_inliers": 10000000})
        self.assertEqual(applied["min_inliers"], 10000000)
        self.assertEqual(rospy.get_param("/tracker/icp/min_inliers"), 10000000)
        lost = self.wait_for_status(lambda s: s.state == TrackingStatus.STATE_LOST,
                                    "ICP failing on the new min_inliers")
        self.assertIn("too few correspondences", lost.failure_reason)

        self.icp.update_configuration({"min_inliers": 200})
        self.wait_for_status(lambda s: s.state == TrackingStatus.STATE_OK and s.frame_index > 0,
                             "ICP succeeding again")

    def test_ekf_noise_reads_back_and_invalid_is_refused(self):
        initial = self.ekf.get_configuration(timeout=TIMEOUT)
        self.assertAlmostEqual(initial["measurement_noise_velocity"], 0.2)
        refused = self.ekf.update_configuration({"measurement_noise_velocity": -1.0})
        self.assertAlmostEqual(refused["measurement_noise_velocity"], 0.2)
        refused = self.ekf.update_configuration({"process_noise_velocity": float("nan")})
        self.assertFalse(math.isnan(refused["process_noise_velocity"]))
        self.assertAlmostEqual(refused["process_noise_velocity"], initial["process_noise_velocity"])

        applied = self.ekf.update_configuration({"measurement_noise_velocity": 0.3,
                                                 "imu_aided_virtual_velocity": False})
        self.assertAlmostEqual(applied["measurement_noise_velocity"], 0.3)
        self.assertFalse(applied["imu_aided_virtual_velocity"])
        self.assertAlmostEqual(rospy.get_param("/tracker/ekf/measurement_noise_velocity"), 0.3)
        # The EKF keeps tracking with the new noise.
        self.wait_for_status(lambda s: s.state == TrackingStatus.STATE_OK, "tracking")


if __name__ == "__main__":
    rostest.rosrun("vicc_tracking", "tracker_reconfigure", TrackerReconfigureTest)
