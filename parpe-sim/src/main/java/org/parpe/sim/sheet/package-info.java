/**
 * Drawings of robots for paper (issue 33): {@link org.parpe.sim.sheet.RobotSheet} lays out an
 * assembled configuration as three orthographic views and a parts list in a
 * {@link org.parpe.core.diagram.Scene}, which the command line writes as SVG or PNG
 * ({@code parpe robot CONFIG --out robot.svg}). Units: the views are drawn at one scale from
 * the assembly's metres; the scene is in pixels.
 */
package org.parpe.sim.sheet;
