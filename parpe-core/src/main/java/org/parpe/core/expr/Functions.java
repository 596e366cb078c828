package org.parpe.core.expr;

import java.util.Locale;

/**
 * The function library of PARSL.md §8 (JEP names and meanings, radians); the names and
 * arities are those of {@link org.parpe.core.lang.Vocabulary}.
 */
final class Functions {
    private Functions() {
    }

    /** One-argument functions. */
    enum F1 {
        SIN, COS, TAN, ASIN, ACOS, ATAN, SINH, COSH, TANH, ASINH, ACOSH, ATANH, LOG, LN, EXP,
        SQRT, ABS, ROUND, FLOOR, CEIL, RAD, DEG;

        /** The name used in messages, made once (evaluation must not allocate). */
        private final String label = name().toLowerCase(Locale.ROOT) + "()";

        String label() {
            return label;
        }

        double apply(double x) {
            switch (this) {
                case SIN: return Math.sin(x);
                case COS: return Math.cos(x);
                case TAN: return Math.tan(x);
                case ASIN: return Math.asin(x);
                case ACOS: return Math.acos(x);
                case ATAN: return Math.atan(x);
                case SINH: return Math.sinh(x);
                case COSH: return Math.cosh(x);
                case TANH: return Math.tanh(x);
                case ASINH: return Math.log(x + Math.sqrt(x * x + 1));
                case ACOSH: return Math.log(x + Math.sqrt(x * x - 1));
                case ATANH: return 0.5 * Math.log((1 + x) / (1 - x));
                case LOG: return Math.log10(x);
                case LN: return Math.log(x);
                case EXP: return Math.exp(x);
                case SQRT: return Math.sqrt(x);
                case ABS: return Math.abs(x);
                case ROUND: return Math.floor(x + 0.5);
                case FLOOR: return Math.floor(x);
                case CEIL: return Math.ceil(x);
                case RAD: return Math.toRadians(x);
                default: return Math.toDegrees(x);
            }
        }
    }

    /** Two-argument functions. */
    enum F2 {
        ATAN2, MOD, MIN, MAX;

        double apply(double a, double b) {
            switch (this) {
                case ATAN2: return Math.atan2(a, b);
                case MOD:
                    if (b == 0) {
                        throw new EvalException(org.parpe.core.text.Msg.MOD_BY_ZERO);
                    }
                    return a % b;
                case MIN: return Math.min(a, b);
                default: return Math.max(a, b);
            }
        }
    }
}
