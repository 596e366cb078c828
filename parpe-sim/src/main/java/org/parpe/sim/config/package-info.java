/**
 * Robot configurations for the simulator (public API): parts (segments, nodes, feet, hubs),
 * plate-to-plate connections with one of four orientations, the initial pose; read from
 * configuration files or made by the standard generators through
 * {@link org.parpe.sim.config.RobotConfigs}.
 */
package org.parpe.sim.config;
