/** Source positions and diagnostics shared by every stage (public API). */
package org.parpe.core.diag;
