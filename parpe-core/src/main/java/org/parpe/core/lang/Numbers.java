package org.parpe.core.lang;

import java.math.BigDecimal;

/**
 * How PARSL writes numbers: the plain numbers of attributes, and the formatting shared by
 * messages and the printer.
 */
public final class Numbers {
    private Numbers() {
    }

    /** The shortest plain decimal that reads back as {@code v} ({@code 2} rather than {@code 2.0}). */
    public static String format(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return new BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
    }

    private static final String[] ORDINALS = {"first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth",
        "ninth", "tenth"};

    /**
     * The place of zero-based {@code index} in words, as a person counts: {@code first} for 0,
     * {@code second} for 1, …, {@code tenth}, then {@code 11th}, {@code 12th}, {@code 21st}, ….
     */
    public static String ordinal(int index) {
        if (index >= 0 && index < ORDINALS.length) {
            return ORDINALS[index];
        }
        int n = index + 1;
        String suffix = n % 100 >= 11 && n % 100 <= 13 ? "th" : switch (n % 10) {
            case 1 -> "st";
            case 2 -> "nd";
            case 3 -> "rd";
            default -> "th";
        };
        return n + suffix;
    }

    /** {@code v} with at most 6 significant digits, for messages ({@code -0.005}). */
    public static String brief(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        return new BigDecimal(v).round(new java.math.MathContext(6)).stripTrailingZeros().toPlainString();
    }

    /**
     * Parses a plain decimal number as PARSL allows in {@code value}, {@code min}, {@code max}
     * and {@code step}: optional sign, digits, optional fraction and exponent. Returns
     * {@code null} for anything else.
     */
    public static Double parsePlain(String text) {
        String t = text.trim();
        if (!t.matches("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?")) {
            return null;
        }
        double v = Double.parseDouble(t);
        return Double.isFinite(v) ? v : null;
    }
}
