using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Runtime.Kinds;

/// <summary>
/// One kind of character in a <see cref="JumpWorld"/>, like one agent size of a navigation map: the planning scene
/// of its reduced model on the world's level, the frozen roadmap baked for it, and the whole-body animator of its
/// rig. Agents of a kind share all three; each is thread-safe to read.
/// </summary>
public sealed class CharacterKind
{
    /// <summary>Creates a kind.</summary>
    /// <param name="scene">The planning scene of the kind's reduced character on the world's level.</param>
    /// <param name="roadmap">A roadmap baked for that scene (same level and character fingerprints; checked by <see cref="JumpWorld.AddKind"/>).</param>
    /// <param name="animator">The whole-body animator of the character's rig on that scene.</param>
    public CharacterKind(PlanningScene scene, Roadmap roadmap, JumpAnimator animator)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(roadmap);
        ArgumentNullException.ThrowIfNull(animator);
        Scene = scene;
        Roadmap = roadmap;
        Animator = animator;
        PathAnimator = new PathAnimationCache(animator, animator.Model);
    }

    /// <summary>
    /// Creates a kind whose paths are animated by <paramref name="pathAnimator"/> instead of <paramref name="animator"/>
    /// (which still places stances and poses agents standing): for tests and tools that animate moves another way.
    /// </summary>
    internal CharacterKind(PlanningScene scene, Roadmap roadmap, JumpAnimator animator, IJumpAnimator pathAnimator)
        : this(scene, roadmap, animator)
    {
        ArgumentNullException.ThrowIfNull(pathAnimator);
        PathAnimator = new PathAnimationCache(pathAnimator, animator.Model);
    }

    /// <summary>
    /// What every jump of this kind costs beyond its flight time, in seconds of walking
    /// (<see cref="Ballistic.Planner.Query.QuerySettings.JumpEffort"/>); <c>null</c> (the default) for the world's
    /// <see cref="Core.WorldSettings.JumpEffort"/>. Finite and not negative (else <see cref="JumpWorld.AddKind"/> refuses the kind).
    /// </summary>
    public float? JumpEffort { get; init; }

    /// <summary>
    /// What a jump of this kind costs on top of <see cref="JumpEffort"/> per metre of its takeoff's energy height, in
    /// seconds of walking per metre (<see cref="Ballistic.Planner.Query.QuerySettings.JumpHeightEffort"/>): a heavy
    /// character that should walk round a wall it could vault gets more. <c>null</c> (the default) for the world's
    /// <see cref="Core.WorldSettings.JumpHeightEffort"/>. Finite and not negative.
    /// </summary>
    public float? JumpHeightEffort { get; init; }

    /// <summary>The character's name.</summary>
    public string Name => Scene.Character.Name;

    /// <summary>The planning scene: level, reduced character, sampler and steering.</summary>
    public PlanningScene Scene { get; }

    /// <summary>The roadmap agents of this kind plan on.</summary>
    public Roadmap Roadmap { get; }

    /// <summary>The whole-body animator.</summary>
    public JumpAnimator Animator { get; }

    /// <summary>
    /// What animates the paths agents of this kind follow: <see cref="Animator"/>, unless made otherwise, each distinct
    /// path solved once for every agent and world of the kind (<see cref="PathAnimationCache"/>).
    /// </summary>
    internal PathAnimationCache PathAnimator { get; }

    /// <summary>The rigged character.</summary>
    public CharacterModel Model => Animator.Model;

    /// <summary>Joints of the rig, one pose rotation each (<see cref="JumpWorld.GetJointRotations"/>).</summary>
    public int JointCount => Model.Rig.Joints.Count;

    /// <summary>Degrees of freedom of the rig, one angle each (<see cref="JumpWorld.GetJointAngles"/>).</summary>
    public int DofCount => Model.Rig.DofCount;
}
