namespace Ballistic.Planner.Steering;

/// <summary>What a refused jump candidate's <see cref="SteeringFailure"/> means, in words a level designer reads.</summary>
internal static class SteeringFailureText
{
    /// <summary>A short phrase for <paramref name="failure"/>, e.g. "no takeoff angle meets every limit at once".</summary>
    public static string Describe(SteeringFailure failure) => failure switch
    {
        SteeringFailure.TooClose => "one stance straight above the other",
        SteeringFailure.TakeoffConeMissesPlane => "the takeoff friction cone does not point along the jump",
        SteeringFailure.LandingConeMissesPlane => "the landing friction cone does not point along the jump",
        SteeringFailure.TakeoffSpeed => "takeoff faster than the character's limit",
        SteeringFailure.LandingSpeed => "landing faster than the character's limit",
        SteeringFailure.LandingCone => "the feet would slip on landing",
        SteeringFailure.EmptyAngleInterval => "no takeoff angle meets every limit at once",
        SteeringFailure.ApexTooHigh => "the arc would rise too high",
        SteeringFailure.Collision => "the trunk would hit the level in flight",
        _ => failure.ToString(),
    };
}
