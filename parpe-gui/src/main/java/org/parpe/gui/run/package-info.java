/** Running scripts from the IDE: the engine thread, targets, speeds and recorded angles. */
package org.parpe.gui.run;
