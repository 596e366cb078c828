/** Scripted use of the IDE from its command line: screenshots, automated steps and the IDE benchmark. */
package org.parpe.gui.automation;
