/**
 * The immutable program model produced by the loader: records, unmodifiable lists, a source
 * position on every node (public API).
 */
package org.parpe.core.model;
