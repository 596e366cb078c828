/** The IDE's files: opening and saving scripts safely, autosave and recovery, and example copies. */
package org.parpe.gui.files;
