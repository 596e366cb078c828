/**
 * The words of PARSL in one place: elements and their attributes, functions with their
 * arities, reserved words, logical variables, the fixed attribute values and how numbers are
 * written ({@link org.parpe.core.lang.Numbers}). The loader checks scripts against it and the
 * IDE's completion offers it (public API: {@link org.parpe.core.lang.Vocabulary},
 * {@link org.parpe.core.lang.Numbers}). Depends on no other package of PARPE.
 */
package org.parpe.core.lang;
