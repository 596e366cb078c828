/** Printing a program model back to PARSL text (public API). */
package org.parpe.core.print;
