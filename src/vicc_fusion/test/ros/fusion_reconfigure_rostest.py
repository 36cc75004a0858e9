#!/usr/bin/python3
"""dynamic_reconfigure of the running fusion node (fusion_reconfigure.test): a valid change of
stable_confidence is applied to the published model (beyond any surfel's confidence it empties
~model, restoring it fills it again), invalid thresholds are refused with the old value kept, and
the tracker inside the node serves its ICP thresholds too."""
import threading
import time
import unittest

import dynamic_reconfigure.client
import rospy
import rostest
from sensor_msgs.msg import PointCloud2

TIMEOUT = 90.0  # wall seconds per step: a loaded machine, a looping bag with a still phase


class FusionReconfigureTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("fusion_reconfigure_test")
        cls.lock = threading.Lock()
        cls.sizes = []
        rospy.Subscriber("/fusion/model", PointCloud2, cls.on_model, queue_size=10)
        cls.fusion = dynamic_reconfigure.client.Client("/fusion/fusion", timeout=TIMEOUT)

    @classmethod
    def on_model(cls, cloud):
        with cls.lock:
            cls.sizes.append(cloud.width * cloud.height)

    def wait_for_model(self, predicate, what, in_a_row=1):
        """Waits for in_a_row consecutive models published after this call that satisfy
        predicate."""
        with self.lock:
            seen = len(self.sizes)
        run = 0
        deadline = time.time() + TIMEOUT
        while time.time() < deadline:
            with self.lock:
                fresh = self.sizes[seen:]
                seen = len(self.sizes)
            for size in fresh:
                run = run + 1 if predicate(size) else 0
                if run >= in_a_row:
                    return
            time.sleep(0.05)
        self.fail("no %d model(s) in a row with %s within %.0f s" % (in_a_row, what, TIMEOUT))

    def test_thresholds_apply_and_invalid_are_refused(self):
        initial = self.fusion.get_configuration(timeout=TIMEOUT)
        self.assertAlmostEqual(initial["stable_confidence"], 3.0)  # SurfelFusionConfig's
        self.assertEqual(initial["unstable_lifetime"], 15)
        self.wait_for_model(lambda size: size > 1000, "stable surfels")

        refused = self.fusion.update_configuration({"stable_confidence": 0.0})  # must be > 0
        self.assertAlmostEqual(refused["stable_confidence"], 3.0)
        self.assertAlmostEqual(rospy.get_param("/fusion/fusion/stable_confidence"), 3.0)
        refused = self.fusion.update_configuration({"max_normal_angle_deg": 95.0,
                                                    "unstable_lifetime": 20})
        self.assertAlmostEqual(refused["max_normal_angle_deg"], 20.0)
        self.assertEqual(refused["unstable_lifetime"], 15)  # a refused request changes nothing

        applied = self.fusion.update_configuration({"stable_confidence": 1e6})
        self.assertAlmostEqual(applied["stable_confidence"], 1e6)
        # A restart of the loop empties the model once; six empty models in a row (3 s at
        # 2 Hz) only come from the threshold.
        self.wait_for_model(lambda size: size == 0, "no surfel stable any more", in_a_row=6)
        self.fusion.update_configuration({"stable_confidence": 3.0})
        self.wait_for_model(lambda size: size > 1000, "stable surfels again")

    def test_the_tracker_inside_is_reconfigurable(self):
        icp = dynamic_reconfigure.client.Client("/fusion/icp", timeout=TIMEOUT)
        self.assertEqual(icp.get_configuration(timeout=TIMEOUT)["min_inliers"], 200)
        self.assertEqual(icp.update_configuration({"min_inliers": 300})["min_inliers"], 300)
        self.assertEqual(rospy.get_param("/fusion/icp/min_inliers"), 300)
        self.assertEqual(icp.update_configuration({"min_inliers": 200})["min_inliers"], 200)


if __name__ == "__main__":
    rostest.rosrun("vicc_fusion", "fusion_reconfigure", FusionReconfigureTest)
