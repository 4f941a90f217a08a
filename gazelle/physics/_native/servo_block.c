/* gazelle: blocks of ros2_control position-servo cycles run inside MuJoCo's step loop.
 *
 * Python plans a block (the targets of every cycle, computed at once) and this loop runs it: for each
 * step and each planned servo group it records the joints' state (what a hardware `read()` sees),
 * updates each position servo's integral from the measured position and writes its command (what
 * gazelle.systems._actuation.PositionServo.control computes, in the same floating-point order, so a
 * block is bit-identical to the Python cycles it replaces), then takes one `mj_step`. It stops after a
 * step whose recorded state left a path tolerance, so the caller aborts the goal at the cycle where
 * the Python cycle would have.
 *
 * A MuJoCo error (mju_error: the arena ran out) inside the loop jumps back here and is returned, with
 * the steps taken, instead of ending the process: the caller grows the arena and runs the rest.
 *
 * Built by gazelle.physics._native (scripts/setup.sh builds it once) against the MuJoCo library the
 * Python bindings load, with -ffp-contract=off: no fused multiply-add may change a rounding.
 */
#include <math.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>
#include <mujoco/mujoco.h>

typedef struct {
  int nservo;             /* servos in the group */
  const int* act;         /* [nservo] actuator ids (ctrl index) */
  const int* qadr;        /* [nservo] qpos address of each servo's joint */
  const int* dadr;        /* [nservo] dof address of each servo's joint */
  const double* target;   /* [ncycle * nservo] position target of each planned cycle */
  const double* velref;   /* [nstep * nservo] velocity reference of each cycle */
  const double* kp;       /* [nservo] (already at least 1e-9) */
  const double* ki;
  const double* kd;
  const double* offset;
  const double* imin;
  const double* imax;
  double* integral;       /* [nservo] in and out */
  double* last;           /* [nservo] time of the servo's last cycle, in and out (NaN: none yet) */
  const double* tol_p;    /* [nservo] path tolerances (0: not checked); NULL: no check */
  const double* tol_v;
  const double* desp;     /* [nstep * nservo] the position the path check compares with (NULL: target) */
  const double* desv;     /* [nstep * nservo] the velocity the path check compares with */
  int nrec;               /* joints recorded each cycle */
  const int* rec_qadr;    /* [nrec] */
  const int* rec_dadr;    /* [nrec] */
  double* rec;            /* [nstep * 3 * nrec] position, velocity, actuator force before each step */
  double* rec_time;       /* [nstep] sim time of each cycle */
  double* ctrl_out;       /* [nservo] the last commands written */
  int cursor;             /* the cycle (row of the per-cycle arrays) the next step runs */
  int violated;           /* out: the cycle whose state left a path tolerance, or -1 */
} gz_servo_group;

static _Thread_local jmp_buf* gz_jump = NULL;
static _Thread_local char gz_message[512];
static void (*gz_previous_handler)(const char*) = NULL;

static void gz_error(const char* msg) {
  if (gz_jump) {
    snprintf(gz_message, sizeof gz_message, "%s", msg);
    longjmp(*gz_jump, 1);
  }
  if (gz_previous_handler) gz_previous_handler(msg);
}

const char* gz_last_error(void) { return gz_message; }

static int gz_cycle(const mjData* d, gz_servo_group* g) {
  const int k = g->cursor;
  const double t = d->time;
  double* r = g->rec + (size_t)k * 3 * g->nrec;
  for (int i = 0; i < g->nrec; i++) {
    r[i] = d->qpos[g->rec_qadr[i]];
    r[g->nrec + i] = d->qvel[g->rec_dadr[i]];
    r[2 * g->nrec + i] = d->qfrc_actuator[g->rec_dadr[i]];
  }
  g->rec_time[k] = t;
  const double* tgt = g->target + (size_t)k * g->nservo;
  const double* vel = g->velref + (size_t)k * g->nservo;
  int left = 0;
  for (int j = 0; j < g->nservo; j++) {
    const double q = d->qpos[g->qadr[j]];
    const double target = tgt[j];
    if (!isnan(g->last[j]) && g->ki[j] != 0.0) {
      const double err = target - q;
      double integral = g->integral[j] + g->ki[j] * err * (t - g->last[j]);
      if (integral < g->imin[j]) integral = g->imin[j]; /* Python's min(max(x, lo), hi) */
      if (g->imax[j] < integral) integral = g->imax[j];
      g->integral[j] = integral;
    }
    g->last[j] = t;
    const double c = target + (g->offset[j] + g->integral[j] + g->kd[j] * vel[j]) / g->kp[j];
    d->ctrl[g->act[j]] = c;
    g->ctrl_out[j] = c;
    if (g->tol_p) {
      /* a trajectory controller commands the next cycle's set point but checks the path at this one's */
      const double ep = (g->desp ? g->desp[(size_t)k * g->nservo + j] : target) - q;
      const double ev = g->desv[(size_t)k * g->nservo + j] - d->qvel[g->dadr[j]];
      if ((g->tol_p[j] > 0.0 && fabs(ep) > g->tol_p[j]) || (g->tol_v[j] > 0.0 && fabs(ev) > g->tol_v[j])) left = 1;
    }
  }
  return left;
}

/* Runs up to nstep steps, each running every group's cycle at its cursor (then advanced). Returns the
 * steps taken (fewer when a group left a path tolerance: that group's `violated` names the cycle), or
 * -(steps taken) - 1 after a MuJoCo error (gz_last_error; the interrupted cycle's cursor is not advanced). */
int gz_run_servo_groups(const mjModel* m, mjData* d, int nstep, int ngroup, gz_servo_group* groups) {
  jmp_buf here;
  volatile int k = 0;
  for (int g = 0; g < ngroup; g++) groups[g].violated = -1;
  gz_previous_handler = mju_user_error == gz_error ? gz_previous_handler : mju_user_error;
  mju_user_error = gz_error;
  gz_jump = &here;
  if (setjmp(here)) {
    gz_jump = NULL;
    return -k - 1;
  }
  for (; k < nstep; k++) {
    int left = 0;
    for (int g = 0; g < ngroup; g++) {
      if (gz_cycle(d, &groups[g])) {
        groups[g].violated = groups[g].cursor;
        left = 1;
      }
    }
    mj_step(m, d);
    for (int g = 0; g < ngroup; g++) groups[g].cursor++;
    if (left) {
      gz_jump = NULL;
      return k + 1;
    }
  }
  gz_jump = NULL;
  return nstep;
}
