/**
 * Loading: includes, resolution and validation of a PARSL file into the immutable model
 * (public API: {@link org.parpe.core.load.ScriptLoader}, {@link org.parpe.core.load.LoadResult}).
 */
package org.parpe.core.load;
