/**
 * The simulator's own words in the user's language: {@link org.parpe.sim.text.SimMsg}, the keys
 * of {@code SimMessages*.properties} (sweeps and optimisation so far; the robot and world
 * readers' messages are {@link org.parpe.core.text.Msg}'s). The language is chosen by
 * {@link org.parpe.core.text.Lang}.
 */
package org.parpe.sim.text;
