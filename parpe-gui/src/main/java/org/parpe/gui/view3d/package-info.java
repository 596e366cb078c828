/** The 3D view: a perspective camera and a painter's-algorithm renderer of simulator snapshots on an SWT canvas. */
package org.parpe.gui.view3d;
