/** {@code parpe diagram}: draws the diagrams of a script to SVG or PNG files. */
package org.parpe.cli.diagram;
