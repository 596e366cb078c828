/**
 * PARPE robots in other tools' formats (issue 34): one {@link org.parpe.sim.bridge.RobotModel}
 * made from an assembled configuration, written as MJCF (MuJoCo), URDF (ROS tools, with the
 * loop-closing joints in a Gazebo block) and SDF (Gazebo), with the simulator's masses,
 * inertias, plate geometry, joint axes and limits, servo strength and speed, and friction.
 */
package org.parpe.sim.bridge;
