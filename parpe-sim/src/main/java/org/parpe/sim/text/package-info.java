/**
 * The simulator's own words in the user's language: {@link org.parpe.sim.text.SimMsg}, the keys
 * of {@code SimMessages*.properties}: every text of this module a user reads (the robot and world
 * readers' messages are {@link org.parpe.core.text.Msg}'s). The language is chosen by
 * {@link org.parpe.core.text.Lang}; file formats this module writes (shard files' framing lines,
 * CSV headers, the report's style sheet) stay as they are.
 */
package org.parpe.sim.text;
