// window.__topayViz: what the page has received and draws, for end-to-end tests.

/**
 * @param app { connection, viewer, layers: {map, scan, robot, trajectory, paths, goal, contacts},
 *              plots, toggles, topics, playback() }
 */
export function installHooks(app) {
  const { connection, viewer, layers, plots, toggles } = app;
  const hooks = {
    get connected() {
      return connection.connected;
    },
    get fps() {
      return viewer.fps;
    },
    get frames() {
      return viewer.frames;
    },
    get webgl() {
      return viewer.renderer !== null;
    },
    get staticRenders() {
      return viewer.cache.renders;
    },
    counts() {
      return {
        mapBlocks: layers.map.blockCount,
        mapVoxels: layers.map.voxels,
        scanPoints: layers.scan.count,
        robotMeshes: layers.robot.meshes,
        trajectoryPoints: layers.trajectory.basePoints,
        eePathPoints: layers.trajectory.eePoints,
        candidatePaths: layers.paths.count,
        goal: layers.goal.present,
        contacts: layers.contacts.count,
        plotSamples: plots.samples,
      };
    },
    topics: app.topics,
    get playback() {
      return app.playback();
    },
    layers: toggles.visible,
    statuses: app.statuses,
  };
  window.__topayViz = hooks;
  return hooks;
}
