/** The IDE's connection to a real robot: the Hardware dialog, its bus session, and the jog. */
package org.parpe.gui.hardware;
