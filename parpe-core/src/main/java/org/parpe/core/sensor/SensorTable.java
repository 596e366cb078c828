package org.parpe.core.sensor;

import java.util.Arrays;

/**
 * The sensor readings of every module for the current tick: a flat, reused array indexed by
 * module index (position of the module ID in ascending order) and {@link Channel}. A
 * sensor source of the scheduler writes measured values into it at step 1 of every tick; the scheduler
 * then applies stimulus overrides and reads it while evaluating expressions.
 */
public final class SensorTable {
    private final int[] ids;
    private final double[] values;

    /** A table for the given module IDs (ascending), every reading 0. */
    public SensorTable(int[] moduleIds) {
        this.ids = moduleIds.clone();
        this.values = new double[ids.length * Channel.count()];
    }

    /** Number of modules. */
    public int moduleCount() {
        return ids.length;
    }

    /** The logical ID of the module at {@code index}. */
    public int idAt(int index) {
        return ids[index];
    }

    /** The module index of logical ID {@code id}, or −1. */
    public int indexOf(int id) {
        int i = Arrays.binarySearch(ids, id);
        return i >= 0 ? i : -1;
    }

    /** The reading of {@code channel} of the module at {@code index}. */
    public double get(int index, Channel channel) {
        return values[slot(index, channel)];
    }

    /** Sets the reading of {@code channel} of the module at {@code index}. */
    public void set(int index, Channel channel, double value) {
        values[slot(index, channel)] = value;
    }

    /** The flat slot of a reading, for compiled expressions. */
    public static int slot(int index, Channel channel) {
        return index * Channel.count() + channel.ordinal();
    }

    /** The raw reading at a flat slot. */
    public double getSlot(int slot) {
        return values[slot];
    }

    /** Sets the raw reading at a flat slot. */
    public void setSlot(int slot, double value) {
        values[slot] = value;
    }
}
