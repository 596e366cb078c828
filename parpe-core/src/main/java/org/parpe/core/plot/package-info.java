/**
 * What every plot of joint angles and sweep results shares, whatever draws it (XChart for the
 * command line's PNG files, the IDE's SWT chart): the one recorder of commanded and measured
 * angles, the one style (colours, commanded dashed, measured solid) and the one choice of round
 * tick values. Pure model code: no drawing library.
 */
package org.parpe.core.plot;
