/** The IDE's entry point and its command-line options (./parpe gui). */
package org.parpe.gui;
