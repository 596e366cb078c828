package org.parpe.core.model;

import org.parpe.core.expr.Expression;

/**
 * One entry of an automaton's {@code times}: {@code T} or {@code T[E]}.
 *
 * @param duration nominal duration in seconds
 * @param exit     exit condition, or {@code null} for a purely time-driven state
 */
public record Timing(Expression duration, Expression exit) {
}
