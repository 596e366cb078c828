/**
 * The IDE's Pose panel (posable programming, PARSL Level I): pose a group in the simulator or on
 * the robot, keep the poses in a list, play them back through the run pipeline, save them as a
 * PARSL.md §12 recording and write them into the open script for other groups.
 */
package org.parpe.gui.pose;
