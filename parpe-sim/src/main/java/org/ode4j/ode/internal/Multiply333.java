package org.ode4j.ode.internal;

import org.ode4j.math.DMatrix3;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;

/**
 * PARPE (issue 36): ODE4j 0.5.3's 3x3 matrix products {@code OdeMath.dMultiply0_333} ({@code a = b c})
 * and {@code dMultiply2_333} ({@code a = b c^T}) with each entry written out, for the tick's hot
 * callers: a geom's rotation from its body's ({@code DxGeom.computePosr}) and a body's inertia in
 * the world frame (QuickStep's stage 0). ODE4j computes every entry by {@code DMatrix3C.dotRowCol}
 * or {@code dotRowRow}, one call per entry that the JIT does not inline (a switch over the row and
 * column, too large), so nine calls and nine switches per product. Each entry here is the same
 * three products added in the same order, {@code (b_i0 c_0j + b_i1 c_1j) + b_i2 c_2j}, and the
 * entries are written in ODE4j's order, row by row: the results are bit-identical, even when
 * {@code a} is one of the factors (Multiply333Test compares them with ODE4j's). Likewise a 3x3
 * matrix times a 3-vector ({@code dMultiply0_331}), whose three entries ODE4j computes by a call
 * to {@code dCalcVectorDot3} and {@code dDOTpq} (arrays) or to {@code dotRow} with a switch over
 * the row ({@code DMatrix3}): QuickStep's {@code inv(M) J^T} and stage 0's momentum and torque.
 */
final class Multiply333 {
	private Multiply333() {
	}

	/** {@code a = b c}, as {@code OdeMath.dMultiply0_333(DMatrix3, DMatrix3C, DMatrix3C)}. */
	static void multiply0(DMatrix3 a, DMatrix3C b, DMatrix3C c) {
		a.set00(b.get00() * c.get00() + b.get01() * c.get10() + b.get02() * c.get20());
		a.set01(b.get00() * c.get01() + b.get01() * c.get11() + b.get02() * c.get21());
		a.set02(b.get00() * c.get02() + b.get01() * c.get12() + b.get02() * c.get22());
		a.set10(b.get10() * c.get00() + b.get11() * c.get10() + b.get12() * c.get20());
		a.set11(b.get10() * c.get01() + b.get11() * c.get11() + b.get12() * c.get21());
		a.set12(b.get10() * c.get02() + b.get11() * c.get12() + b.get12() * c.get22());
		a.set20(b.get20() * c.get00() + b.get21() * c.get10() + b.get22() * c.get20());
		a.set21(b.get20() * c.get01() + b.get21() * c.get11() + b.get22() * c.get21());
		a.set22(b.get20() * c.get02() + b.get21() * c.get12() + b.get22() * c.get22());
	}

	/**
	 * {@code b c} into the 3x4 block of {@code a} at {@code ofs} (rows 4 numbers apart), as
	 * {@code OdeMath.dMultiply0_333(double[], int, DMatrix3C, DMatrix3C)}.
	 */
	static void multiply0(double[] a, int ofs, DMatrix3C b, DMatrix3C c) {
		a[ofs] = b.get00() * c.get00() + b.get01() * c.get10() + b.get02() * c.get20();
		a[ofs + 1] = b.get00() * c.get01() + b.get01() * c.get11() + b.get02() * c.get21();
		a[ofs + 2] = b.get00() * c.get02() + b.get01() * c.get12() + b.get02() * c.get22();
		a[ofs + 4] = b.get10() * c.get00() + b.get11() * c.get10() + b.get12() * c.get20();
		a[ofs + 5] = b.get10() * c.get01() + b.get11() * c.get11() + b.get12() * c.get21();
		a[ofs + 6] = b.get10() * c.get02() + b.get11() * c.get12() + b.get12() * c.get22();
		a[ofs + 8] = b.get20() * c.get00() + b.get21() * c.get10() + b.get22() * c.get20();
		a[ofs + 9] = b.get20() * c.get01() + b.get21() * c.get11() + b.get22() * c.get21();
		a[ofs + 10] = b.get20() * c.get02() + b.get21() * c.get12() + b.get22() * c.get22();
	}

	/** {@code a = b c^T}, as {@code OdeMath.dMultiply2_333(DMatrix3, DMatrix3C, DMatrix3C)}. */
	static void multiply2(DMatrix3 a, DMatrix3C b, DMatrix3C c) {
		a.set00(b.get00() * c.get00() + b.get01() * c.get01() + b.get02() * c.get02());
		a.set01(b.get00() * c.get10() + b.get01() * c.get11() + b.get02() * c.get12());
		a.set02(b.get00() * c.get20() + b.get01() * c.get21() + b.get02() * c.get22());
		a.set10(b.get10() * c.get00() + b.get11() * c.get01() + b.get12() * c.get02());
		a.set11(b.get10() * c.get10() + b.get11() * c.get11() + b.get12() * c.get12());
		a.set12(b.get10() * c.get20() + b.get11() * c.get21() + b.get12() * c.get22());
		a.set20(b.get20() * c.get00() + b.get21() * c.get01() + b.get22() * c.get02());
		a.set21(b.get20() * c.get10() + b.get21() * c.get11() + b.get22() * c.get12());
		a.set22(b.get20() * c.get20() + b.get21() * c.get21() + b.get22() * c.get22());
	}

	/**
	 * {@code a = B c} for the 3x3 matrix {@code B} stored as rows 4 numbers apart from {@code ofsB}
	 * and the 3-vector {@code c}, as {@code OdeMath.dMultiply0_331(double[], int, double[], int,
	 * double[], int)}, which takes a call to {@code dCalcVectorDot3} and one to {@code dDOTpq} per
	 * entry (QuickStep's {@code inv(M) J^T}, a row's angular block times its body's inverse inertia,
	 * runs it twice for every constraint row). Each entry is {@code (B_i0 c_0 + B_i1 c_1) + B_i2 c_2},
	 * as ODE4j adds it. {@code c} is read once, before {@code a} is written: {@code a} must not
	 * overlap {@code c} (at every caller they are different arrays).
	 */
	static void multiply0_331(double[] a, int ofsA, double[] b, int ofsB, double[] c, int ofsC) {
		double c0 = c[ofsC];
		double c1 = c[ofsC + 1];
		double c2 = c[ofsC + 2];
		a[ofsA] = b[ofsB] * c0 + b[ofsB + 1] * c1 + b[ofsB + 2] * c2;
		a[ofsA + 1] = b[ofsB + 4] * c0 + b[ofsB + 5] * c1 + b[ofsB + 6] * c2;
		a[ofsA + 2] = b[ofsB + 8] * c0 + b[ofsB + 9] * c1 + b[ofsB + 10] * c2;
	}

	/**
	 * {@code a = b c} for a 3x3 matrix and a 3-vector, as {@code OdeMath.dMultiply0_331(DVector3,
	 * DMatrix3C, DVector3C)}, whose {@code DMatrix3C.dotRow} per entry is a call with a switch over
	 * the row (QuickStep's stage 0, a body's angular momentum and gyroscopic torque). All three
	 * entries are computed before {@code a} is written, as ODE4j does, so {@code a} may be {@code c}.
	 */
	static void multiply0_331(DVector3 a, DMatrix3C b, DVector3C c) {
		double c0 = c.get0();
		double c1 = c.get1();
		double c2 = c.get2();
		a.set(b.get00() * c0 + b.get01() * c1 + b.get02() * c2,
				b.get10() * c0 + b.get11() * c1 + b.get12() * c2,
				b.get20() * c0 + b.get21() * c1 + b.get22() * c2);
	}
}
