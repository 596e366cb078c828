/** The IDE window: menus, tool bar, status bar, files, autosave, examples, automation and benchmarks. */
package org.parpe.gui.app;
